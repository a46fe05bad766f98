// strip_points() and Hydro::outputs() must not touch the heap once the Input is sized (called
// every step). Global operator new is replaced in this executable to count allocations.
#include <atomic>
#include <cstdlib>
#include <new>

#include <catch2/catch.hpp>

#include "fowtsim/testing/allocation_counter.hpp"

#include "fowtsim/core/rotation.hpp"
#include "fowtsim/hydro/benchmarks.hpp"
#include "fowtsim/hydro/oc3.hpp"

using fowtsim::testing::allocations;
using fowtsim::testing::counting;

using namespace fowtsim;
using namespace fowtsim::hydro;

TEST_CASE("hydro strip_points and outputs allocate nothing", "[unit][hydro]") {
  Params p = oc3_hywind_params();
  p.current.profile = CurrentParams::Profile::power_law;
  p.current.surface_speed_m_s = 1.0;
  p.current.reference_depth_m = 320.0;
  Hydro::Input in = make_input(p);
  Points points(3, node_count(p));
  const benchmarks::DeepWaterAiry wave{3.0, 10.0};
  Hydro::outputs(p, in, {});  // warm-up: the Gauss tables are built on first use
  allocations = 0;
  counting = true;
  double sum = 0.0;
  for (int k = 0; k < 50; ++k) {
    in.platform.orientation = euler123_to_matrix(Vec3(0.01 * k, 0.2, 0.0));
    strip_points(p, in.platform, in.surface_elevation_m, points);
    benchmarks::fill_kinematics(wave, 0.1 * k, points, in);
    sum += Hydro::outputs(p, in, {}).total[0];
  }
  counting = false;
  CHECK(allocations == 0);
  CHECK(std::isfinite(sum));
}

TEST_CASE("hydro with potential flow: outputs at the stages and advance allocate nothing (both methods)", "[unit][hydro]") {
  for (const RadiationMethod method : {RadiationMethod::convolution, RadiationMethod::state_space}) {
    Params p = oc3_hywind_params();
    RadiationTable table;
    for (int k = 1; k <= 40; ++k) {
      table.frequencies_rad_s.push_back(0.1 * k);
      const double w = 0.1 * k;
      table.damping.push_back(Mat6::Identity() * 1e5 * w * w * std::exp(-w));
    }
    table.added_mass_infinite_frequency = Mat6::Identity() * 1e6;
    RadiationOptions options;
    options.method = method;
    options.step_s = 0.05;
    options.window_s = 20.0;
    p.potential_flow = PotentialFlowParams{make_radiation_model(table, options), true};
    Hydro::Input in = make_input(p);
    Hydro::State state = Hydro::make_state(p, in);
    Hydro::outputs(p, in, state);
    allocations = 0;
    counting = true;
    double sum = 0.0;
    for (int k = 0; k < 50; ++k) {
      in.platform.velocity_m_s = Vec3(std::sin(0.3 * k), 0.0, 0.1);
      for (double c : {0.0, 0.5, 0.5, 1.0}) {
        in.time_s = 0.05 * (k + c);
        sum += Hydro::outputs(p, in, state).total[0];
      }
      Hydro::advance(p, in, 0.05 * k, 0.05, state);
    }
    counting = false;
    CHECK(allocations == 0);
    CHECK(std::isfinite(sum));
  }
}
