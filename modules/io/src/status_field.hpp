#pragma once
// Private helper of the writers that keep a run's status in a fixed-width field of their header
// (the .out's line 5, the .outb's description), rewritten in place when the run ends.
#include <cstddef>
#include <string>

namespace fowtsim::io::detail {

inline constexpr std::size_t kStatusWidth = 160;  // characters of the status field

// The status as it fits in the field: one line, at most kStatusWidth characters, padded with
// blanks so that rewriting it never moves what follows it.
inline std::string status_field(std::string status) {
  for (char& c : status)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  if (status.size() > kStatusWidth) status = status.substr(0, kStatusWidth - 3) + "...";
  status.resize(kStatusWidth, ' ');
  return status;
}

}  // namespace fowtsim::io::detail
