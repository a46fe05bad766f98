#pragma once
// "did you mean `x`?" for a misspelt name, by the rule of the deck schema validator
// (modules/io/src/schema_validate.cpp): the closest candidate within an edit distance of
// max(2, length / 3), or the candidate the written name is a prefix of up to a `_unit` suffix.
// Here the comparison ignores case too (channel names are case-insensitive in OpenFAST).
#include <algorithm>
#include <cctype>
#include <numeric>
#include <string>
#include <string_view>
#include <vector>

namespace fowtsim::driver {

inline std::size_t edit_distance_nocase(std::string_view a, std::string_view b) {
  auto lower = [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); };
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = diagonal + (lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
    }
  }
  return row[b.size()];
}

// The closest candidate, or "" when none is close enough to be a typo.
inline std::string closest_name(std::string_view written, const std::vector<std::string>& candidates) {
  const std::size_t limit = std::max<std::size_t>(2, written.size() / 3);
  const std::string* best = nullptr;
  std::size_t best_distance = limit + 1;
  for (const std::string& candidate : candidates) {
    const bool suffix_forgotten = candidate.starts_with(std::string(written) + "_");
    const std::size_t distance = suffix_forgotten ? 1 : edit_distance_nocase(written, candidate);
    if (distance < best_distance) {
      best = &candidate;
      best_distance = distance;
    }
  }
  return best ? *best : std::string();
}

// "did you mean `x`?", or "".
inline std::string did_you_mean(std::string_view written, const std::vector<std::string>& candidates) {
  const std::string best = closest_name(written, candidates);
  return best.empty() ? std::string() : "did you mean `" + best + "`?";
}

}  // namespace fowtsim::driver
