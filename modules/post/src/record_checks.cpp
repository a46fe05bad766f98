#include "fowtsim/post/record_checks.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::post {

void check_time_order(std::span<const double> time_s, const std::string& source) {
  const auto back = std::adjacent_find(time_s.begin(), time_s.end(), [](double a, double b) { return b < a; });
  if (back == time_s.end()) return;
  const std::size_t row = static_cast<std::size_t>(back - time_s.begin()) + 2;  // 1-based row of the later time
  throw InputError({"post", std::nullopt, "Time", ""},
                   fmt::format("{}: time goes backwards at data row {}: {} s after {} s (rows out of order, or two runs "
                               "appended?); windows, cycles and spectra need increasing time",
                               source, row, *(back + 1), *back));
}

void check_no_nan(std::span<const double> time_s, std::span<const double> values, std::size_t first_row,
                  const std::string& source, const std::string& channel) {
  const auto nan = std::find_if(values.begin(), values.end(), [](double v) { return std::isnan(v); });
  if (nan == values.end()) return;
  const std::size_t index = static_cast<std::size_t>(nan - values.begin());
  throw InputError({"post", std::nullopt, channel, ""},
                   fmt::format("{}: channel {} is NaN from data row {} (t = {} s) on: its statistics, cycles and "
                               "spectrum would be meaningless; choose a --window before it, or --channels without it",
                               source, channel, first_row + index + 1, time_s[index]));
}

}  // namespace fowtsim::post
