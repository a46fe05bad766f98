#pragma once
// Run time against error for the OC3 spar (DESIGN.md §8 tier 4), for `fowtsim bench hydro`, and
// the closed-form deep-water Airy wave the tests and benchmarks use as input (computed here, not by
// the waves module, which hydro may not depend on).
#include <string>
#include <vector>

#include "fowtsim/hydro/hydro.hpp"

namespace fowtsim::hydro::benchmarks {

// Linear deep-water regular wave travelling along +x (k = ω²/g; seed 004 "harmonic wave"):
//   η = a cos θ, θ = k x − ω t;  u = a ω e^{kz} (cos θ, 0, sin θ);
//   u̇ = a ω² e^{kz} (sin θ, 0, −cos θ);  p_dyn = ρ g a e^{kz} cos θ.
struct DeepWaterAiry {
  double amplitude_m = 1.0;    // a = H/2 [m]
  double period_s = 10.0;      // T [s]
  double gravity_m_s2 = 9.80665;
  double water_density_kg_m3 = 1025.0;
  double omega() const;        // 2π/T [rad/s]
  double wavenumber() const;   // ω²/g [rad/m]
};

// Fills input.fluid_* at `points` (from strip_points) with the wave at time t.
void fill_kinematics(const DeepWaterAiry& wave, double t_s, const Points& points, Hydro::Input& input);

struct BenchRow {
  std::string name;          // case
  int strip_nodes = 0;       // kinematics nodes (strips + ends) of the run
  int quadrature_points = 0; // Gauss points of the cut hydrostatic integral
  double us_per_call = 0.0;  // wall time of one Hydro::outputs() [µs]
  double us_per_strip_points = 0.0;  // wall time of one strip_points() [µs]; 0 where not timed
  double force_error = 0.0;  // max over the case of |F − F_fine| / max |F_fine| [-]
  double moment_error = 0.0; // the same for the moment about the reference point [-]
  std::string reference;     // what "fine" is
};

// OC3 spar with oc3_hywind_params(): (1) a regular wave H 6 m, T 10 s, over one period, vs 4× the
// strips; (2) hydrostatics at 10° pitch vs 4× the Gauss points; (3) Morison alone at 10° pitch in the
// same wave vs 4× the strips. `repeats` calls are timed per case.
std::vector<BenchRow> oc3_bench(int repeats = 20000);

}  // namespace fowtsim::hydro::benchmarks
