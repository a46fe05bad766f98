#pragma once
// Text the command line prints: the run summary and verification tables (the comparison table:
// compare/comparison_table.hpp).
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "run/run_types.hpp"

namespace fowtsim::driver {

void print_run_summary(std::FILE* out, const RunReport& report);

// One line of `fowtsim verify`: a measured metric against its tolerance and the source of both.
struct VerificationRow {
  std::string case_name;   // e.g. "coupling"
  std::string metric;      // what was measured
  double value;            // measured value
  std::string tolerance;   // acceptance, as text, e.g. "1 ± 0.1"
  std::string source;      // where the expectation comes from
  bool pass;
};
void print_verification(std::FILE* out, const std::vector<VerificationRow>& rows);

// Width of a printed table's first column: its longest case name, at least "case".
template <typename Rows, typename Name>
std::size_t name_width(const Rows& rows, Name name) {
  std::size_t w = 4;
  for (const auto& r : rows) w = std::max(w, std::string(name(r)).size());
  return w;
}

}  // namespace fowtsim::driver
