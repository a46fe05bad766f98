#include "fowtsim/io/suggest.hpp"

#include <algorithm>
#include <cctype>
#include <numeric>

namespace fowtsim::io {
namespace {

std::size_t edit_distance(std::string_view a, std::string_view b, LetterCase letter_case) {
  auto same = [&](char x, char y) {
    if (letter_case == LetterCase::matters) return x == y;
    return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
  };
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = diagonal + (same(a[i - 1], b[j - 1]) ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
    }
  }
  return row[b.size()];
}

}  // namespace

std::string closest_name(std::string_view written, const std::vector<std::string>& candidates, LetterCase letter_case) {
  const std::size_t limit = std::max<std::size_t>(2, written.size() / 3);
  const std::string* best = nullptr;
  std::size_t best_distance = limit + 1;
  for (const std::string& candidate : candidates) {
    const bool suffix_forgotten = candidate.starts_with(std::string(written) + "_");
    const std::size_t distance = suffix_forgotten ? 1 : edit_distance(written, candidate, letter_case);
    if (distance < best_distance) {
      best = &candidate;
      best_distance = distance;
    }
  }
  return best ? *best : std::string();
}

std::string did_you_mean(std::string_view written, const std::vector<std::string>& candidates, LetterCase letter_case) {
  const std::string best = closest_name(written, candidates, letter_case);
  return best.empty() ? std::string() : "did you mean `" + best + "`?";
}

}  // namespace fowtsim::io
