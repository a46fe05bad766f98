// Dynamic benchmarks of seed 000 §2.5.1: time-step convergence of the piecewise-linear scheme
// (Table 2.1) with both integrators of the locally linear system.
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/beam/benchmarks.hpp"

using namespace fowtsim;
using namespace fowtsim::beam;

TEST_CASE("time-step convergence of the steel strip, generalized-alpha (Table 2.1)",
          "[verification][beam]") {
  DynamicOptions opt;
  opt.max_increment_rad = 10.0;  // the coarse rows are meant to be inaccurate, not to stop
  const std::vector<double> dts{128e-5, 64e-5, 32e-5, 16e-5, 8e-5, 4e-5, 2e-5, 1e-5};
  const auto rows = benchmarks::strip_time_step_study(200, opt, dts, 5e-6);
  for (const auto& r : rows) {
    INFO("dt " << r.dt_s << ": rms " << r.rms_vs_reference << " (" << 100 * r.relative << " %)");
    CHECK_FALSE(r.failed);  // ρ∞ = 0 damps the unresolved tip whip: every row runs
  }
  // The scheme converges: the error falls with every halving of the step …
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) CHECK(rows[i + 1].rms_vs_reference < rows[i].rms_vs_reference);
  // … to the seed's accuracy class at the finest steps (seed Table 2.1 at 1e-5 s: 0.026 % with
  // ode45 inside each step; generalized-α adds its own O(Δt²) error, measured 0.10 %).
  CHECK(rows.back().relative < 0.002);
  // Second order once the step resolves the tip whip (measured log2 ratios ≈ 2.2–2.5 below 4e-5 s).
  CHECK(rows[rows.size() - 3].order > 1.8);
}

TEST_CASE("time-step convergence with the ARKODE Dormand-Prince integrator",
          "[verification][beam]") {
  // The seed's own integrator (ode45, RelTol 1e-6). Explicit steps are bounded by the stiffest
  // mode (∝ N²), so this check runs on 50 elements to stay fast; the 200-element table is printed
  // by `fowtsim verify beam-timestep`.
  DynamicOptions opt;
  opt.integrator = Integrator::erk;
  opt.max_increment_rad = 10.0;
  const std::vector<double> dts{16e-5, 8e-5, 4e-5, 2e-5};
  const auto rows = benchmarks::strip_time_step_study(50, opt, dts, 5e-6);
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) {
    INFO("dt " << rows[i].dt_s << " → " << rows[i + 1].dt_s << ": relative " << rows[i].relative << " → "
               << rows[i + 1].relative);
    REQUIRE_FALSE(rows[i + 1].failed);
    CHECK(rows[i + 1].rms_vs_reference < rows[i].rms_vs_reference);  // convergent, as Table 2.1
  }
  CHECK(rows.back().relative < 0.01);  // seed Table 2.1 at 2e-5 s: 0.064 % (200 elements)
}

TEST_CASE("a step that breaks the small-angle assumption stops with a clear message", "[unit][beam]") {
  // The closing moment on the strip turns the tip segment by radians within 1 ms: with the
  // default 0.1 rad limit the step must be refused, naming the remedy.
  const BeamModel model = discretise(benchmarks::steel_strip(), 50);
  BeamState state = make_state(model);
  BeamInput in;
  in.tip_load[3] = benchmarks::steel_strip_rollup_moment();
  DynamicStepper stepper(model, DynamicOptions{});
  CHECK_THROWS_WITH(stepper.step(in, 1e-3, state),
                    Catch::Contains("small-angle") && Catch::Contains("reduce the beam time step"));
}
