#pragma once
// Run time of the multibody (DESIGN.md §8 tier 4), for `fowtsim bench multibody`.
#include <string>
#include <vector>

namespace fowtsim::multibody {

struct BenchRow {
  std::string name;             // case
  int steps = 0;                // large steps timed
  double dt_s = 0.0;            // large step [s]
  int substeps = 0;             // RK4 substeps per large step
  double us_per_step = 0.0;     // wall time of one advance() [µs]
  double us_per_evaluation = 0.0;  // wall time of one evaluate() (kinematics + M + solve) [µs]
  double us_per_outputs = 0.0;  // wall time of one outputs() (incl. inverse dynamics) [µs]
  double energy_drift = 0.0;    // |ΔE|/E over the run of the free system (accuracy alongside cost) [-]
};

// OC3-Hywind, gravity off, no external loads, rotor at 12.1 rpm, platform tumbling slowly:
// one row per large step in {0.02, 0.05, 0.1} s, `steps` large steps each.
std::vector<BenchRow> bench_multibody(int steps = 20000);

}  // namespace fowtsim::multibody
