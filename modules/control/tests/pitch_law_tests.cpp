// Speed filter, gain-scheduled PI pitch law, anti-windup and sample-time logic against the
// published description (Jonkman et al., NREL/TP-500-38060, §7.1 and §7.3) in closed form.
#include <cmath>
#include <numbers>

#include <catch2/catch.hpp>

#include "fowtsim/control/baseline_controller.hpp"
#include "fowtsim/control/presets.hpp"
#include "fowtsim/control/verification.hpp"

using namespace fowtsim::control;
using Controller = BaselineController;

namespace {

ControllerInput measured(double w, double pitch_rad) {
  ControllerInput u;
  u.generator_speed_rad_s = w;
  u.blade_pitch_rad = {pitch_rad, pitch_rad, pitch_rad};
  return u;
}

}  // namespace

TEST_CASE("speed filter: single pole at 0.25 Hz, exact step response", "[verification][control]") {
  // Intent: ω_f follows a step of the measured speed as 1 − exp(−ω_c t) with ω_c = 2π·0.25 Hz
  // (38060 §7.1), at any call interval (the recursion is the exact discretisation of the pole).
  const BaselineParams p = nrel5mw_land_baseline();
  // Published corner 1.570796 rad/s = 2π × 0.25 Hz rounded to 7 digits: 1e-6 relative.
  CHECK(p.filter_corner_rad_s == Approx(2.0 * std::numbers::pi * 0.25).epsilon(1e-6));
  // 1e-12 relative: exact discretisation, round-off only.
  CHECK(verification::filter_step_response_error(p) < 1e-12);
}

TEST_CASE("PI pitch step: gains scheduled by 1/(1+θ/θ_K)", "[verification][control]") {
  // Intent: one update from a steady pitch θ₀ with a constant speed error e adds
  // G_K(θ₀) (K_P e + K_I e Δt) to the pitch (38060 §7.3: integral term seeded at θ₀, gains × G_K).
  const BaselineParams p = nrel5mw_land_baseline();
  for (double theta0 : {0.0, 0.05, 0.1, 0.2, 0.35}) {
    Controller::State s = Controller::make_state(p);
    const double w = p.reference_speed_rad_s + 0.05, dt = 0.0125;  // small error: G_K K_P e < 8°/s Δt
    Controller::advance(p, measured(w, theta0), 0.0, dt, s);       // seeds filter and integrator
    Controller::advance(p, measured(w, theta0), dt, dt, s);
    const double gk = 1.0 / (1.0 + theta0 / 0.1099965);            // PC_KK, PUBLISHED.md
    const double expected = theta0 + gk * (0.01882681 * 0.05 + 0.008068634 * 0.05 * dt);
    INFO("θ₀ = " << theta0);
    // 1e-12 rad: closed form, round-off only.
    CHECK(std::abs(s.pitch_demand_rad[0] - expected) <= 1e-12);
  }
}

TEST_CASE("anti-windup: the integral term stays within the pitch limits", "[verification][control]") {
  // Intent: after 100 s below rated (error < 0, pitch at θ_min = 0) the integrator has not wound
  // down, so a speed above reference raises the pitch at the very next update by exactly the
  // proportional + one-step integral term; the same at the upper limit (38060 §7.3).
  const BaselineParams p = nrel5mw_land_baseline();
  const double dt = 0.0125;
  Controller::State s = Controller::make_state(p);
  double t = 0.0, theta = 0.0;
  for (; t < 100.0; t += dt) {
    Controller::advance(p, measured(100.0, theta), t, dt, s);
    theta = s.pitch_demand_rad[0];
  }
  CHECK(theta == 0.0);
  CHECK(s.speed_error_integral_rad == 0.0);  // clamped at θ_min / (G_K K_I) = 0
  // Put the filtered speed just above reference (State is plain data) and take one update: the
  // first positive error acts at once, with nothing wound up to unwind.
  s.filtered_speed_rad_s = p.reference_speed_rad_s + 0.05;
  Controller::advance(p, measured(p.reference_speed_rad_s + 0.05, 0.0), t, dt, s);
  const double e = s.filtered_speed_rad_s - p.reference_speed_rad_s;
  CHECK(s.pitch_demand_rad[0] == Approx(0.01882681 * e + 0.008068634 * e * dt).epsilon(1e-12));

  // Upper limit: far above reference for 100 s, the pitch rides to θ_max = 90° at 8°/s and stays.
  Controller::State high = Controller::make_state(p);
  theta = 0.0;
  for (t = 0.0; t < 100.0; t += dt) {
    Controller::advance(p, measured(200.0, theta), t, dt, high);
    theta = high.pitch_demand_rad[0];
  }
  CHECK(theta == p.max_pitch_rad);
  const double gk = 1.0 / (1.0 + p.max_pitch_rad / p.gain_schedule_pitch_rad);
  // The integral term is held at θ_max (1e-12 relative: a clamp and a product).
  CHECK(gk * p.integral_gain * high.speed_error_integral_rad == Approx(p.max_pitch_rad).epsilon(1e-12));
}

TEST_CASE("sample time: updates when the sample time has elapsed", "[unit][control]") {
  // Intent: the DISCON "LastTime" logic. OC3 sample time 0.00125 s: called every 0.0005 s the law
  // updates every 3rd call (elapsed 0.0015 s); called every 0.0125 s it updates at every call.
  const BaselineParams p = oc3_hywind_baseline();
  for (auto [step, expected_every] : {std::pair{0.0005, 3}, std::pair{0.0125, 1}}) {
    Controller::State s = Controller::make_state(p);
    int updates = 0;
    double last = 0.0;
    for (int k = 0; k <= 300; ++k) {
      Controller::advance(p, measured(110.0 + 0.01 * k, 0.0), k * step, step, s);
      if (k > 0 && s.last_update_time_s != last) {
        ++updates;
        CHECK(std::lround((s.last_update_time_s - last) / step) == expected_every);
      }
      last = s.last_update_time_s;
    }
    CHECK(updates == 300 / expected_every);
  }
}

TEST_CASE("equal pitch limits hold the blades there: a parked rotor stays feathered", "[unit][control]") {
  // Intent: DLC 6.1 parks the rotor by making the feather angle both limits. At zero rotor speed
  // (the speed error as negative as it gets) the law must keep the pitch at feather, not drive it
  // towards fine pitch, and the limits must pass validation.
  BaselineParams p = nrel5mw_land_baseline();
  p.min_pitch_rad = p.max_pitch_rad;
  REQUIRE_NOTHROW(validate(p));
  Controller::State s = Controller::make_state(p);
  const double dt = 0.0125;
  for (int k = 0; k < 800; ++k) Controller::advance(p, measured(0.0, p.max_pitch_rad), k * dt, dt, s);  // 10 s parked
  for (const double demand : s.pitch_demand_rad) CHECK(demand == p.max_pitch_rad);
  // Limits the other way round stay an error.
  p.min_pitch_rad = p.max_pitch_rad + 0.01;
  CHECK_THROWS_WITH(validate(p), Catch::Contains("max_pitch_rad"));
}
