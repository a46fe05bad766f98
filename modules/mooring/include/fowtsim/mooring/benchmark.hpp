#pragma once
// Cost of the mooring per call, for `fowtsim bench hydro` (DESIGN.md §8: numbers printed by a
// tool, never asserted). Each row times one way of calling the module along the same platform
// trajectory (surge 10 ± 4 m, heave ± 0.5 m, pitch 3 ± 2°, yaw ± 2°, 60 s at 0.05 s steps).
#include <string>
#include <vector>

namespace fowtsim::mooring {

struct MooringBenchRow {
  std::string case_name;          // e.g. "oc3 catenary, warm start"
  int calls = 0;                  // timed calls
  double microseconds_per_call = 0.0;  // wall time per call [µs]
  double iterations_per_line = 0.0;    // mean solver iterations per line and call [-]
};

// OC3 catenary (3 lines) warm- and cold-started, its analytic 6×6 stiffness, and the seed's taut
// four-line system; `repeats` passes over the trajectory (1200 calls each).
std::vector<MooringBenchRow> bench_mooring(int repeats = 5);

}  // namespace fowtsim::mooring
