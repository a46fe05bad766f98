#pragma once
// Verification of the glue code on the toy coupled oscillators (issue 2, item 8): error against
// the exact matrix-exponential solution as ΔT and n vary, observed order of accuracy, and the
// largest stable ΔT of each coupling mode.
#include <vector>

#include "coupling/coupling_mode.hpp"
#include "fowtsim/toy/fast_oscillator.hpp"
#include "fowtsim/toy/slow_oscillator.hpp"

namespace fowtsim::driver {

struct ToyProblem {
  toy::SlowOscillator::Params slow;
  toy::FastOscillator::Params fast;
};

// The study's problem: slow ω ≈ 1 rad/s (M = 1000 kg), fast ω ≈ 20 rad/s (m = 10 kg, 1 % of M),
// 1 % damping on the fast mass, slow mass released from X = 1 m.
ToyProblem study_problem();

struct ErrorSample {
  CouplingMode mode;
  int substeps;           // n
  double dt_coupling_s;   // ΔT [s]
  double slow_error;      // max_t |X − X_exact| / max_t |X_exact| over the run [-]
  double fast_error;      // max_t |q − q_exact| / max_t |q_exact| over the run [-]
  bool finite;            // false when the run diverged (errors then meaningless)
};

// Runs the toy problem to t_max_s with the given coupling and measures the errors at every
// large step against the exact solution.
ErrorSample measure_error(const ToyProblem& problem, CouplingMode mode, int substeps, double dt_coupling_s,
                          double t_max_s);

// Steps the coupled toy problem to t_max_s and returns the final slow position [m]; the loop
// alone, without the exact solution, for timing.
double run_only(const ToyProblem& problem, CouplingMode mode, int substeps, double dt_coupling_s, double t_max_s);

struct OrderRow {
  CouplingMode mode;
  int substeps;
  std::vector<ErrorSample> samples;  // ΔT halving
  double slow_order;                 // log2(e(2ΔT)/e(ΔT)) at the two smallest ΔT
  double fast_order;
};

// Error vs ΔT (halving from dt_start_s, levels times) for one mode and n.
OrderRow measure_order(const ToyProblem& problem, CouplingMode mode, int substeps, double dt_start_s, int levels,
                       double t_max_s);

struct StabilityResult {
  CouplingMode mode;
  int substeps;
  double largest_stable_dt_s;    // largest ΔT on the scan grid that stayed bounded [s]
  double first_unstable_dt_s;    // next grid value, which did not [s]
};

// Scans ΔT on a geometric grid (ratio 2^(1/8)) from dt_min_s upwards; a run is stable when its
// mechanical energy stays below twice the initial energy and finite over horizon_s (the exact
// solution's energy never grows: it is damped).
StabilityResult measure_stability(const ToyProblem& problem, CouplingMode mode, int substeps, double dt_min_s,
                                  double dt_max_s, double horizon_s);

}  // namespace fowtsim::driver
