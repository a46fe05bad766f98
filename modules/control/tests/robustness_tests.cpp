// Bad parameters stop before the run (InputError naming the key); bad values during the run give
// NumericalError with time and quantity, never NaN (DESIGN.md §7).
#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include <catch2/catch.hpp>

#include "fowtsim/control/baseline_controller.hpp"
#include "fowtsim/control/presets.hpp"
#include "fowtsim/core/error.hpp"

using namespace fowtsim;
using namespace fowtsim::control;

TEST_CASE("bad baseline parameters throw InputError naming the key", "[unit][control]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::pair<std::string, std::function<void(BaselineParams&)>> cases[] = {
      {"sample_time_s", [](BaselineParams& p) { p.sample_time_s = -0.01; }},
      {"filter_corner_rad_s", [](BaselineParams& p) { p.filter_corner_rad_s = 0.0; }},
      {"region2_start_speed_rad_s", [](BaselineParams& p) { p.region2_start_speed_rad_s = 60.0; }},
      {"rated_generator_speed_rad_s", [](BaselineParams& p) { p.rated_generator_speed_rad_s = 90.0; }},
      {"rated_power_W", [nan](BaselineParams& p) { p.rated_power_W = nan; }},
      {"max_torque_rate_N_m_s", [](BaselineParams& p) { p.max_torque_rate_N_m_s = -1.0; }},
      {"integral_gain", [](BaselineParams& p) { p.integral_gain = 0.0; }},
      {"gain_schedule_pitch_rad", [](BaselineParams& p) { p.gain_schedule_pitch_rad = 0.0; }},
      {"max_pitch_rad", [](BaselineParams& p) { p.max_pitch_rad = -0.1; }},
      {"max_pitch_rate_rad_s", [](BaselineParams& p) { p.max_pitch_rate_rad_s = 0.0; }},
      {"generator_efficiency", [](BaselineParams& p) { p.generator_efficiency = 1.5; }},
      // k ω² would never meet the 2½ line: no transition speed.
      {"region2_gain_N_m_s2", [](BaselineParams& p) { p.region2_gain_N_m_s2 = 20.0; }},
      {"max_torque_N_m", [](BaselineParams& p) { p.max_torque_N_m = 40000.0; }},
  };
  for (const auto& [key, spoil] : cases) {
    BaselineParams p = nrel5mw_land_baseline();
    spoil(p);
    INFO(key);
    try {
      BaselineController::make_state(p);
      FAIL("no InputError");
    } catch (const InputError& e) {
      CHECK_THAT(e.what(), Catch::Contains("controller." + key));
    }
  }
  // Several problems are reported together.
  BaselineParams p = nrel5mw_land_baseline();
  p.filter_corner_rad_s = -1.0;
  p.max_pitch_rate_rad_s = nan;
  try {
    validate(p);
    FAIL("no InputError");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains("filter_corner_rad_s") && Catch::Contains("max_pitch_rate_rad_s"));
  }
  CHECK_THROWS_AS(region3_torque_from_name("constant_speed"), InputError);
  CHECK(region3_torque_from_name("constant_torque") == Region3Torque::constant_torque);
  CHECK_NOTHROW(validate(nrel5mw_land_baseline()));
  CHECK_NOTHROW(validate(oc3_hywind_baseline()));
}

TEST_CASE("non-finite measurements and time reversal give NumericalError", "[unit][control]") {
  const BaselineParams p = oc3_hywind_baseline();
  BaselineController::State s = BaselineController::make_state(p);
  ControllerInput u;
  u.generator_speed_rad_s = 110.0;
  BaselineController::advance(p, u, 1.0, 0.0125, s);
  ControllerInput bad = u;
  bad.blade_pitch_rad[1] = std::numeric_limits<double>::quiet_NaN();
  try {
    BaselineController::advance(p, bad, 1.0125, 0.0125, s);
    FAIL("no NumericalError");
  } catch (const NumericalError& e) {
    CHECK(e.context().variable == "blade 2 pitch");
    CHECK(e.context().time_s == 1.0125);
  }
  bad = u;
  bad.generator_speed_rad_s = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(BaselineController::advance(p, bad, 1.0125, 0.0125, s), NumericalError);
  CHECK_THROWS_AS(BaselineController::advance(p, u, 0.5, 0.0125, s), NumericalError);   // earlier than 1.0
  CHECK_THROWS_AS(BaselineController::advance(p, u, 1.0125, 0.0, s), NumericalError);   // dt ≤ 0
  // A repeated call at the same time changes nothing (a corrector pass may re-sample).
  const BaselineController::State before = s;
  BaselineController::advance(p, u, 1.0, 0.0125, s);
  CHECK(s.filtered_speed_rad_s == before.filtered_speed_rad_s);
  CHECK(s.torque_demand_N_m == before.torque_demand_N_m);
}

TEST_CASE("state copy reproduces the trajectory; outputs are pure", "[unit][control]") {
  // Conformance (STYLE.md): a copied State continues identically; outputs() has no side effect.
  const BaselineParams p = nrel5mw_land_baseline();
  BaselineController::State a = BaselineController::make_state(p);
  ControllerInput u;
  for (int k = 0; k < 400; ++k) {
    u.generator_speed_rad_s = 115.0 + 10.0 * std::sin(0.01 * k);
    BaselineController::advance(p, u, 0.0125 * k, 0.0125, a);
    u.blade_pitch_rad = BaselineController::outputs(p, u, a).blade_pitch_rad;
  }
  BaselineController::State b = a;
  for (int k = 400; k < 800; ++k) {
    u.generator_speed_rad_s = 115.0 + 10.0 * std::sin(0.01 * k);
    BaselineController::advance(p, u, 0.0125 * k, 0.0125, a);
    BaselineController::advance(p, u, 0.0125 * k, 0.0125, b);
    const auto ya = BaselineController::outputs(p, u, a);
    const auto ya2 = BaselineController::outputs(p, u, a);
    CHECK(ya.generator_torque_N_m == BaselineController::outputs(p, u, b).generator_torque_N_m);
    CHECK(ya.blade_pitch_rad == ya2.blade_pitch_rad);
    u.blade_pitch_rad = ya.blade_pitch_rad;
  }
  // Channels in OpenFAST names and units.
  const auto channels = BaselineController::channels(p);
  REQUIRE(channels.size() == 6);
  CHECK(channels[0].name == "GenTq");
  CHECK(channels[0].unit == "kN-m");
  CHECK(channels[1].name == "GenPwr");
  CHECK(channels[2].name == "BlPitchC1");
  CHECK(channels[5].name == "GenSpeed");
  std::array<double, 6> values{};
  ControllerOutput y;
  y.generator_torque_N_m = 43093.55;
  y.generator_power_W = 5e6;
  y.blade_pitch_rad = {0.1, 0.2, 0.3};
  y.generator_speed_rad_s = 122.9096;
  BaselineController::channel_values(p, y, values);
  CHECK(values[0] == Approx(43.09355));
  CHECK(values[1] == Approx(5000.0));
  CHECK(values[2] == Approx(5.729578));
  CHECK(values[5] == Approx(1173.7).epsilon(1e-5));
  std::array<double, 5> short_values{};
  CHECK_THROWS_AS(BaselineController::channel_values(p, y, short_values), InputError);
}
