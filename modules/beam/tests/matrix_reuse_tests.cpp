// Reuse of generalized-α's factored step matrix (DynamicOptions::matrix_max_*): the residual is
// exact at every step, so a reused matrix only perturbs the correction; these checks bound what
// that costs against rebuilding the matrix every step (matrix_max_age = 1, the seed's scheme), on
// the two rotating benchmarks whose step matrix changes most: Kane's spin-up (the frame speeds up
// from rest to 6 rad/s, the soft beam dips by 6 % of its length and the centrifugal stiffening
// builds up) and the §2.5.3 beam (bent by 30 % of its length, flapping at 26 rad/s).
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/beam/beam_outputs.hpp"
#include "fowtsim/beam/rotating_benchmarks.hpp"
#include "fowtsim/beam/solvers.hpp"
#include "fowtsim/core/error.hpp"

using namespace fowtsim;
using namespace fowtsim::beam;

namespace {

// In-plane tip deflection of Kane's beam every 0.02 s over the 20 s spin-up case.
std::vector<double> kane_tip(const DynamicOptions& options, double dt = 0.005) {
  const BeamModel model = discretise(benchmarks::kane_beam(), 30);
  BeamState state = make_state(model);
  DynamicStepper stepper(model, options);
  std::vector<double> tip;
  BeamInput input;
  const long steps = std::lround(20.0 / dt), per_sample = std::lround(0.02 / dt);
  for (long k = 0; k < steps; ++k) {
    input.frame = benchmarks::kane_frame((k + stepper.input_time_fraction()) * dt);
    stepper.step(input, dt, state);
    if ((k + 1) % per_sample == 0) tip.push_back(beam_outputs(model, state).tip_displacement_m.y());
  }
  return tip;
}

// Tip displacement of the §2.5.3 beam every 5 ms over 2 s from its static start.
std::vector<Vec3> rotating_tip(const DynamicOptions& options, double dt = 0.005) {
  const BeamModel model = discretise(benchmarks::rotating_steel_beam(), 30);
  BeamState state = make_state(model);
  StaticOptions static_options;
  static_options.load_steps = 10;
  solve_static(model, benchmarks::rotating_beam_input(model, 0.0), state, static_options);
  DynamicStepper stepper(model, options);
  std::vector<Vec3> tip;
  const long steps = std::lround(2.0 / dt), per_sample = std::lround(0.005 / dt);
  for (long k = 0; k < steps; ++k) {
    stepper.step(benchmarks::rotating_beam_input(model, (k + stepper.input_time_fraction()) * dt), dt, state);
    if ((k + 1) % per_sample == 0) tip.push_back(beam_outputs(model, state).tip_displacement_m);
  }
  return tip;
}

double max_abs(const std::vector<double>& a) {
  double m = 0.0;
  for (double v : a) m = std::max(m, std::abs(v));
  return m;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) m = std::max(m, std::abs(a[k] - b[k]));
  return m;
}

DynamicOptions rebuilt_every_step() {
  DynamicOptions o;
  o.matrix_max_age = 1;
  return o;
}

}  // namespace

TEST_CASE("reusing the step matrix through Kane's spin-up changes the tip by a negligible amount",
          "[verification][beam]") {
  const std::vector<double> exact = kane_tip(rebuilt_every_step());
  const std::vector<double> reused = kane_tip(DynamicOptions{});
  const std::vector<double> half_step = kane_tip(rebuilt_every_step(), 0.0025);
  DynamicOptions no_rotation_limit;
  no_rotation_limit.matrix_max_rotation_rad = std::numeric_limits<double>::infinity();
  no_rotation_limit.matrix_max_age = 1 << 30;
  const double d_reused = max_difference(reused, exact);
  const double d_time = max_difference(exact, half_step);
  INFO("max |tip| " << max_abs(exact) << " m; reuse changes it by " << d_reused
                    << " m; halving the step by " << d_time << " m");
  // Negligible against the time-discretisation error: below 1 % of what halving Δt changes, the
  // bound DynamicOptions states (measured 0.5 %: 2.1e-7 m against 4.4e-5 m).
  CHECK(d_reused < 1e-2 * d_time);
  // The rotation limit is what keeps the reuse stable: without it the matrix soon carries the
  // stiff axial direction of an earlier shape across the soft bending one and the steps blow up.
  CHECK_THROWS_AS(kane_tip(no_rotation_limit), NumericalError);
}

TEST_CASE("reusing the step matrix on the rotating straight beam changes the tip by a negligible amount",
          "[verification][beam]") {
  const std::vector<Vec3> exact = rotating_tip(rebuilt_every_step());
  const std::vector<Vec3> reused = rotating_tip(DynamicOptions{});
  double d = 0.0, scale = 0.0;
  for (std::size_t k = 0; k < exact.size(); ++k) {
    d = std::max(d, (reused[k] - exact[k]).norm());
    scale = std::max(scale, exact[k].norm());
  }
  const std::vector<Vec3> half_step = rotating_tip(rebuilt_every_step(), 0.0025);
  double d_time = 0.0;
  for (std::size_t k = 0; k < exact.size(); ++k) d_time = std::max(d_time, (half_step[k] - exact[k]).norm());
  INFO("max |tip| " << scale << " m; reuse changes it by " << d << " m; halving the step by " << d_time << " m");
  // Below 0.1 % of the time-discretisation error (measured 0.015 %: 1.6e-5 m against 0.106 m;
  // DynamicOptions states 1 %). The rotation limit decides here: at 0.01 rad the change is 5 mm.
  CHECK(d < 1e-3 * d_time);
}
