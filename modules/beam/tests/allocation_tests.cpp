// The dynamic step must not touch the heap once the stepper is built (issue 3: "no heap
// allocation in the step loop"). Global operator new is replaced in this test executable to count
// allocations while a flag is set.
#include <atomic>
#include <cstdlib>
#include <new>

#include <catch2/catch.hpp>

#include "fowtsim/testing/allocation_counter.hpp"

#include "fowtsim/beam/benchmarks.hpp"
#include "fowtsim/beam/riser.hpp"
#include "fowtsim/beam/solvers.hpp"

using fowtsim::testing::allocations;
using fowtsim::testing::counting;

using namespace fowtsim;
using namespace fowtsim::beam;

TEST_CASE("a generalized-alpha beam step allocates nothing", "[unit][beam]") {
  const BeamModel model = discretise(benchmarks::steel_strip(), 49);
  BeamState state = make_state(model);
  BeamInput in;
  in.frame.angular_velocity_rad_s = Vec3(0.0, 1.0, 0.0);
  in.frame.gravity_m_s2 = Vec3(0.0, -9.81, 0.0);
  in.node_loads.assign(model.node_count(), Vec6::Zero());
  DynamicStepper stepper(model, DynamicOptions{});
  stepper.step(in, 1e-4, state);  // warm-up: first-step acceleration solve
  allocations = 0;
  counting = true;
  for (int k = 0; k < 100; ++k) stepper.step(in, 1e-4, state);
  counting = false;
  CHECK(allocations == 0);
}

TEST_CASE("a riser step (flow, still water, a moved tip) allocates nothing", "[unit][beam][riser]") {
  // Seed §3.5.3's case (a) during its stretch ramp: the pipe's pressures, the water's drag and
  // added mass, and the held tip's prescribed motion all in the step.
  const riser::RiserSetup setup = riser::seed_case('a');
  const BeamModel model = riser::riser_model(setup, 100);
  BeamState state = make_state(model);
  BeamInput in;
  DynamicStepper stepper(model, DynamicOptions{});
  riser::riser_input(setup, 1e-3, in);
  stepper.step(in, 1e-3, state);  // warm-up: first-step acceleration solve, the pressures' workspace
  allocations = 0;
  counting = true;
  for (int k = 1; k < 101; ++k) {
    riser::riser_input(setup, (k + 1) * 1e-3, in);
    stepper.step(in, 1e-3, state);
  }
  counting = false;
  CHECK(allocations == 0);
  CHECK(state.tip_offset_m.z() > 0.0);  // the top did move
}
