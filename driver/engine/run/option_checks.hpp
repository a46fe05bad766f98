#pragma once
// Checks of command-line values that say what is wanted ("--tmax abc": "expected a positive
// number of seconds, found 'abc'") instead of a conversion failure.
#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace fowtsim::driver {

// "" when `text` is a finite number > 0 written in full, else "expected <what>, found '<text>'".
inline std::string positive_number_problem(const std::string& text, const std::string& what) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size() && v > 0 && std::isfinite(v)) return "";
  } catch (const std::exception&) {
  }
  return fmt::format("expected {}, found '{}'", what, text);
}

}  // namespace fowtsim::driver
