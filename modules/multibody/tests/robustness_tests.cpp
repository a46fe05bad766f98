// Robustness: rotation through 90° pitch (Euler 1-2-3 gimbal lock), bad decks rejected before the
// run with the key named, zero inertia entries, non-finite loads reported with context.
#include <cmath>
#include <numbers>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation.hpp"
#include "fowtsim/multibody/multibody.hpp"
#include "fowtsim/multibody/oc3.hpp"
#include "test_support.hpp"

using namespace fowtsim;
using namespace fowtsim::multibody;
using Catch::Matchers::Contains;
using fowtsim::multibody::testing::FreeProvider;
using fowtsim::multibody::testing::LambdaProvider;

TEST_CASE("torque-free rotation about a principal axis passes through 90 deg pitch exactly",
          "[verification][multibody][robustness]") {
  // Base with diagonal inertia about its CM at the reference point, nothing else: spinning about
  // y_b at q is an exact steady solution, T_gb(t) = R_y(q t) (Euler's equations with ω ∥ principal axis).
  Params p;
  p.platform.mass_kg = 1.0e6;
  p.platform.roll_inertia_kg_m2 = 3.0e8;
  p.platform.pitch_inertia_kg_m2 = 2.0e8;
  p.platform.yaw_inertia_kg_m2 = 1.0e8;
  p.tower.top_height_m = 10.0;
  p.tower.station_fraction = {0.0, 1.0};
  p.tower.mass_density_kg_m = {0.0, 0.0};
  p.rotor.hub_inertia_kg_m2 = 1.0;
  p.rotor.tip_radius_m = 1.0;
  p.max_step_s = 0.05;
  const double q = 0.1;
  p.initial_conditions.platform_angular_velocity_deg_s = Vec3(0.0, q * 180.0 / std::numbers::pi, 0.0);
  const Model model = make_model(p);
  State s = Multibody::make_state(model);
  FreeProvider provider;
  double worst = 0.0;
  bool passed_lock = false;
  for (int n = 0; n < 600; ++n) {  // 30 s: pitch 0 → 3 rad, through π/2
    Multibody::advance(model, provider, n * 0.05, 0.05, s);
    const double t = (n + 1) * 0.05;
    const Mat3 exact = euler123_to_matrix(Vec3(0.0, q * t, 0.0));
    worst = std::max(worst, (s.orientation.toRotationMatrix() - exact).norm());
    AppliedLoads l;
    l.gravity = false;
    const Output out = Multibody::outputs(model, l, s);
    for (double v : out.channels) REQUIRE(std::isfinite(v));
    if (std::abs(q * t - std::numbers::pi / 2) < 0.003) passed_lock = true;
  }
  CHECK(passed_lock);
  CHECK(worst < 1e-12);  // a steady spin is integrated exactly up to round-off
}

TEST_CASE("decks with impossible structure data are rejected before the run, naming the key",
          "[unit][multibody][robustness]") {
  {
    Params p = oc3_hywind_params();
    p.platform.mass_kg = -1.0;
    p.nacelle.shaft_tilt_deg = 95.0;
    REQUIRE_THROWS_AS(make_model(p), InputError);
    REQUIRE_THROWS_WITH(make_model(p), Contains("structure.platform.mass_kg") && Contains("structure.nacelle.shaft_tilt_deg"));
  }
  {  // flexible drivetrain without generator inertia: the generator DOF has no inertia
    Params p = oc3_hywind_params();
    p.drivetrain.generator_inertia_kg_m2 = 0.0;
    REQUIRE_THROWS_WITH(make_model(p), Contains("drivetrain.generator_inertia_kg_m2"));
    p.drivetrain.torsional_flexibility = false;  // rigid shaft: the rotor carries it, a physical model
    CHECK_NOTHROW(make_model(p));
  }
  {  // no pitch inertia: every inertia zero and all masses on the axis (only the generator's
     // 534 kg·m² about the tilted shaft remains, which gives roll and yaw but not pitch)
    Params p = oc3_hywind_params();
    p.platform.roll_inertia_kg_m2 = p.platform.pitch_inertia_kg_m2 = p.platform.yaw_inertia_kg_m2 = 0.0;
    p.nacelle.mass_kg = 0.0;
    p.nacelle.yaw_inertia_kg_m2 = 0.0;
    p.rotor.hub_mass_kg = p.rotor.hub_inertia_kg_m2 = 0.0;
    p.rotor.blade_mass_kg = p.rotor.blade_first_mass_moment_kg_m = p.rotor.blade_second_mass_moment_kg_m2 = 0.0;
    p.tower.mass_density_kg_m.assign(11, 0.0);
    p.platform.cm_m = Vec3::Zero();
    p.drivetrain.torsional_flexibility = false;
    REQUIRE_THROWS_AS(make_model(p), InputError);
    REQUIRE_THROWS_WITH(make_model(p), Contains("singular") && Contains("pitch"));
  }
  {  // a nacelle yaw inertia below its own mass's share about the yaw axis
    Params p = oc3_hywind_params();
    p.nacelle.yaw_inertia_kg_m2 = 1.0e5;
    REQUIRE_THROWS_WITH(make_model(p), Contains("nacelle.yaw_inertia_kg_m2"));
  }
}

TEST_CASE("zero platform inertia entries still give a physical model", "[unit][multibody][robustness]") {
  // Platform as a point mass (zero inertias, as a deck might leave them): the tower, nacelle and
  // rotor still give every rotation inertia, so the model runs and conserves energy.
  Params p = oc3_hywind_params();
  p.platform.roll_inertia_kg_m2 = p.platform.pitch_inertia_kg_m2 = p.platform.yaw_inertia_kg_m2 = 0.0;
  p.drivetrain.torsional_damping_N_m_s_rad = 0.0;
  p.initial_conditions.rotor_speed_rpm = 12.1;
  p.initial_conditions.platform_angular_velocity_deg_s = Vec3(0.2, 0.5, 0.1);
  const Model model = make_model(p);
  State s = Multibody::make_state(model);
  FreeProvider provider;
  const Invariants i0 = invariants(model, s, false);
  for (int n = 0; n < 500; ++n) Multibody::advance(model, provider, n * 0.02, 0.02, s);
  const Invariants i1 = invariants(model, s, false);
  const double drift = std::abs(i1.kinetic_energy_J + i1.potential_energy_J - i0.kinetic_energy_J - i0.potential_energy_J) /
                       (i0.kinetic_energy_J + i0.potential_energy_J);
  WARN("zero platform inertia: energy drift over 10 s " << drift);
  CHECK(drift < 1e-6);  // the tolerance of the conservation test
}

TEST_CASE("a NaN load stops the step with module, time and variable", "[unit][multibody][robustness]") {
  const Model model = make_model(oc3_hywind_params());
  State s = Multibody::make_state(model);
  LambdaProvider provider([](double, const State&, AppliedLoads& out) { out.platform_force_N.x() = std::nan(""); });
  try {
    Multibody::advance(model, provider, 12.0, 0.02, s);
    FAIL("no exception");
  } catch (const NumericalError& e) {
    CHECK(e.context().module == "multibody");
    REQUIRE(e.context().time_s.has_value());
    CHECK(*e.context().time_s == Approx(12.0));
    CHECK_THAT(e.context().variable, Contains("acceleration"));
  }
}
