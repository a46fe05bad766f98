#pragma once
// Checks of a record before it is analysed: statistics, rainflow cycles and spectra of a record
// whose time goes backwards or whose channel holds NaN would be numbers without meaning, so
// `fowtsim post` refuses them with the row and time that break the rule.
#include <cstddef>
#include <span>
#include <string>

namespace fowtsim::post {

// Throws InputError naming `source` when the time column decreases anywhere, with the first such
// data row (1-based) and its time and the time before it.
void check_time_order(std::span<const double> time_s, const std::string& source);

// Throws InputError naming `source` and `channel` when `values` holds a NaN, with its first data
// row (first_row + index, 1-based) and time.
void check_no_nan(std::span<const double> time_s, std::span<const double> values, std::size_t first_row,
                  const std::string& source, const std::string& channel);

}  // namespace fowtsim::post
