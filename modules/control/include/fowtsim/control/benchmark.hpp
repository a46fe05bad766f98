#pragma once
// Cost of one controller call (DESIGN.md §8 tier 4), for `fowtsim bench control`.
#include <string>
#include <vector>

namespace fowtsim::control {

struct ControlBenchRow {
  std::string name;        // case
  int calls = 0;           // advance() + outputs() calls timed
  double ns_per_call = 0;  // wall time of one advance() + outputs() [ns]
};

// The built-in law (land and OC3 parameter sets) and, when `discon_library_path` is not empty, a
// DISCON library called through the swap array (infile "oc3_hywind", as the test DISCON expects),
// each driven by the same generator-speed signal crossing regions 2 to 3 at ΔT = 0.0125 s.
std::vector<ControlBenchRow> bench_control(const std::string& discon_library_path = "", int calls = 200000);

}  // namespace fowtsim::control
