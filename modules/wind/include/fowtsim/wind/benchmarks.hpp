#pragma once
// Timings for `fowtsim bench aero` (DESIGN.md §8: printed, never asserted).
#include <string>
#include <vector>

namespace fowtsim::wind {

struct WindBenchRow {
  std::string name;              // what was timed
  double wall_time_s = 0.0;      // total wall time of the case [s]
  double cpu_time_s = 0.0;       // process CPU time of the case [s] (std::clock; TurbSim's summary reports CPU)
  double microseconds_per_call = 0.0;  // per velocity lookup [µs]; 0 for the generation row
  std::string details;           // sizes, method counts, …
};

// (1) generating the OC3 deck's field: IEC Kaimal NTM class B, 12 m/s at 90 m, 31×31 grid
//     145 m × 145 m, 630 s at 0.05 s (TurbSim 90m_12mps_twr.inp; TurbSim's summary: 1,657 s CPU);
//     `duration_fraction` < 1 generates that fraction of the 630 s (memory-limited machines);
// (2) velocity lookups in that field at `lookups` points along a rotor circle (full field), and
//     in a power-law field (analytic profile).
std::vector<WindBenchRow> bench_wind(double duration_fraction = 1.0, int lookups = 1'000'000);

}  // namespace fowtsim::wind
