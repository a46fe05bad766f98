#pragma once
// The fields of one line of a numeric text table (a recorded sea, an OpenFAST uniform wind file):
// separated by blanks or commas, as the formats users bring write them. Views into the line.
#include <string_view>
#include <vector>

namespace fowtsim {

inline bool is_field_separator(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == ','; }

inline std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_field_separator(line[i])) ++i;
    std::size_t j = i;
    while (j < line.size() && !is_field_separator(line[j])) ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

}  // namespace fowtsim
