#include "verify/coupling_study.hpp"

#include <cmath>

#include "coupling/multi_rate_scheduler.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/toy/exact_solution.hpp"

namespace fowtsim::driver {
namespace {

using Scheduler = MultiRateScheduler<toy::SlowOscillator, toy::FastOscillator>;

Eigen::Vector4d state_of(const Scheduler& s) {
  return {s.slow_state().position_m, s.slow_state().velocity_m_s, s.fast_state().position_m,
          s.fast_state().velocity_m_s};
}

// The study's one time loop: the scheduler's large steps to its t_max, calling keep_going after
// each; a false answer stops there. A NumericalError of a diverging run propagates.
template <class KeepGoing>
void run_large_steps(Scheduler& scheduler, KeepGoing&& keep_going) {
  for (long i = 0; i < scheduler.settings().large_steps(); ++i) {
    scheduler.step();
    if (!keep_going(scheduler)) return;
  }
}

CouplingSettings settings_for(CouplingMode mode, int substeps, double dt_coupling_s, double t_max_s) {
  CouplingSettings s;
  s.mode = mode;
  s.substeps = substeps;
  s.dt_coupling_s = dt_coupling_s;
  s.t_max_s = t_max_s;
  return s;
}

}  // namespace

ToyProblem study_problem() {
  ToyProblem p;
  p.slow = {1000.0, 1000.0, 0.0, 1.0, 1e6};
  // c = 2 ζ √(k m) with ζ = 1 %.
  p.fast = {10.0, 4000.0, 2.0 * 0.01 * std::sqrt(4000.0 * 10.0), 0.0, 1e6};
  return p;
}

ErrorSample measure_error(const ToyProblem& problem, CouplingMode mode, int substeps, double dt_coupling_s,
                          double t_max_s) {
  Scheduler scheduler(problem.slow, problem.fast, settings_for(mode, substeps, dt_coupling_s, t_max_s));
  const toy::ExactSolution exact(problem.slow, problem.fast);
  double slow_err = 0, fast_err = 0, slow_max = 0, fast_max = 0;
  ErrorSample sample{mode, substeps, dt_coupling_s, 0.0, 0.0, true};
  try {
    run_large_steps(scheduler, [&](const Scheduler& s) {
      const Eigen::Vector4d z = state_of(s), ze = exact.state_at(s.time_s());
      slow_err = std::max(slow_err, std::abs(z[0] - ze[0]));
      fast_err = std::max(fast_err, std::abs(z[2] - ze[2]));
      slow_max = std::max(slow_max, std::abs(ze[0]));
      fast_max = std::max(fast_max, std::abs(ze[2]));
      return true;
    });
  } catch (const NumericalError&) {
    sample.finite = false;
  }
  sample.slow_error = slow_err / slow_max;
  sample.fast_error = fast_err / fast_max;
  return sample;
}

double run_only(const ToyProblem& problem, CouplingMode mode, int substeps, double dt_coupling_s, double t_max_s) {
  Scheduler scheduler(problem.slow, problem.fast, settings_for(mode, substeps, dt_coupling_s, t_max_s));
  run_large_steps(scheduler, [](const Scheduler&) { return true; });
  return scheduler.slow_state().position_m;
}

OrderRow measure_order(const ToyProblem& problem, CouplingMode mode, int substeps, double dt_start_s, int levels,
                       double t_max_s) {
  OrderRow row{mode, substeps, {}, NAN, NAN};
  double dt = dt_start_s;
  for (int level = 0; level < levels; ++level, dt *= 0.5) {
    row.samples.push_back(measure_error(problem, mode, substeps, dt, t_max_s));
  }
  if (levels >= 2) {
    const ErrorSample& coarse = row.samples[levels - 2];
    const ErrorSample& fine = row.samples[levels - 1];
    if (!coarse.finite || !fine.finite) return row;  // NaN order: a diverged run has none
    row.slow_order = std::log2(coarse.slow_error / fine.slow_error);
    row.fast_order = std::log2(coarse.fast_error / fine.fast_error);
  }
  return row;
}

StabilityResult measure_stability(const ToyProblem& problem, CouplingMode mode, int substeps, double dt_min_s,
                                  double dt_max_s, double horizon_s) {
  const double ratio = std::pow(2.0, 1.0 / 8.0);
  StabilityResult result{mode, substeps, 0.0, NAN};
  const double e0 = toy::mechanical_energy(problem.slow, problem.fast,
                                           {problem.slow.initial_position_m, 0.0, problem.fast.initial_position_m, 0.0});
  for (double dt = dt_min_s; dt <= dt_max_s; dt *= ratio) {
    // Whole number of steps over at least the horizon.
    const double t_max = std::ceil(horizon_s / dt) * dt;
    Scheduler scheduler(problem.slow, problem.fast, settings_for(mode, substeps, dt, t_max));
    bool stable = true;
    try {
      run_large_steps(scheduler, [&](const Scheduler& s) {
        stable = toy::mechanical_energy(problem.slow, problem.fast, state_of(s)) < 2.0 * e0;
        return stable;
      });
    } catch (const NumericalError&) {
      stable = false;
    }
    if (!stable) {
      result.first_unstable_dt_s = dt;
      return result;
    }
    result.largest_stable_dt_s = dt;
  }
  return result;
}

}  // namespace fowtsim::driver
