#pragma once
// Run time of one rotor aerodynamic evaluation (DESIGN.md §8 tier 4), for `fowtsim bench aero`.
#include <string>
#include <vector>

#include "fowtsim/aero/params.hpp"

namespace fowtsim::aero::benchmarks {

// The blade resampled to `nodes` nodes equally spaced in span between the first and last node:
// chord, twist and AC offsets linear in span, each node takes the airfoil of the nearest original
// node (one airfoil per node, as AeroDyn). Throws InputError for nodes < 2.
Params resample_blade(const Params& params, int nodes);

struct BenchRow {
  std::string name;                 // case
  int blades = 0;                   // B
  int nodes_per_blade = 0;          // N
  double us_per_evaluation = 0.0;   // wall time of one evaluate() (all B·N nodes + rotor sums) [µs]
  double us_per_node = 0.0;         // the same per node [µs]
  double residual_calls_per_node = 0.0;  // mean R(φ) evaluations per node of the induction solver
  double power_W = 0.0;             // RtAeroPwr of the case (a sanity value) [W]
};

// NREL 5MW-like rigid rotor (precone 2.5°, tilt 5°, hub radius 1.5 m) at 11 m/s, 11.87 rpm, 0°
// pitch, azimuth stepped each call: the blade of `params` resampled to 17 and 49 nodes and as
// given. `repeats` evaluations are timed per row.
std::vector<BenchRow> rotor_evaluation_bench(const Params& params, int repeats = 2000);

}  // namespace fowtsim::aero::benchmarks
