// The baseline controller in closed loop with a quasi-steady NREL 5-MW rotor (fowtsim/control/verification.hpp):
// steady pitch against the published operating table, and bounded responses to wind steps.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <catch2/catch.hpp>

#include "fowtsim/control/baseline_controller.hpp"
#include "fowtsim/control/presets.hpp"
#include "fowtsim/control/verification.hpp"

using namespace fowtsim::control;
using fowtsim::control::verification::LoopSample;
using fowtsim::control::verification::Rotor;
using fowtsim::control::verification::SteadyLoop;
using fowtsim::control::verification::equilibrium_pitch_rad;
using fowtsim::control::verification::run_loop;
using fowtsim::control::verification::settle_closed_loop;

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr double kRpm = 30.0 / std::numbers::pi;
constexpr double kStep = 0.0125;  // OC3 deck's DT, the large step the controller runs at

}  // namespace

TEST_CASE("steady pitch of the closed loop matches the published operating table", "[verification][control]") {
  // Intent: issue 6 — the baseline controller on a quasi-steady rotor settles at the published
  // pitch within 0.5° and at the rated rotor speed 12.1 rpm (PUBLISHED.md operating table, welib
  // NREL5MW_Oper.csv). Start: 12.1 rpm, pitch 0; land gains settle in 150 s, the detuned OC3 gains
  // (K_I 9× smaller) in 600 s. Both region-3 torque laws give the same equilibrium (T ω = P at ω_ref).
  const Rotor rotor;
  struct Point { double wind, pitch_deg; };
  const Point table[] = {{12.0, 3.45}, {15.0, 10.26}, {20.0, 17.32}, {25.0, 22.96}};
  for (const auto& [name, p, t_end] : {std::tuple{"land", nrel5mw_land_baseline(), 150.0},
                                       std::tuple{"OC3", oc3_hywind_baseline(), 600.0}}) {
    for (const Point& point : table) {
      const SteadyLoop steady = settle_closed_loop(rotor, p, point.wind, t_end);
      const double ideal_deg =
          equilibrium_pitch_rad(rotor, point.wind, p.reference_speed_rad_s / rotor.gearbox_ratio, p.rated_power_W) * kDeg;
      INFO(name << " U = " << point.wind << " m/s: pitch " << steady.pitch_deg << "° (published " << point.pitch_deg
                << "°, rotor model's equilibrium " << ideal_deg << "°), drift " << steady.pitch_drift_deg
                << "°, rotor speed " << steady.rotor_speed_rpm << " rpm");
      // Published table: 0.5° (issue 6). Measured |Δ| ≤ 0.17°, the spread of the CCBlade Cp table
      // against the OpenFAST operating points (see the consistency test below).
      CHECK(std::abs(steady.pitch_deg - point.pitch_deg) <= 0.5);
      // The controller itself: it must settle on the rotor model's exact equilibrium (integral
      // action removes the speed error). Measured ≤ 1.5e-6° off and ≤ 1.3e-5° of drift over the
      // last 20 s (OC3 at 12 m/s, the slowest); tolerance 1e-4°.
      CHECK(std::abs(steady.pitch_deg - ideal_deg) <= 1e-4);
      CHECK(steady.pitch_drift_deg <= 1e-4);
      // Rated rotor speed 12.1 rpm = PC_RefSpd / 97 (PUBLISHED.md; 122.9096 rad/s is 12.1000004 rpm).
      // Measured ≤ 2.5e-6 rpm; tolerance 5e-5 rpm.
      CHECK(std::abs(steady.rotor_speed_rpm - 12.1) <= 5e-5);
    }
  }
}

TEST_CASE("rotor model consistency: Cp table against OpenFAST AeroDyn operating points", "[verification][control]") {
  // Intent: bound how far the quasi-steady rotor of the tests is from OpenFAST's aerodynamics, so
  // the pitch comparison above is read correctly. RtAeroCp of the OpenFAST v5 rigid-rotor runs at
  // the published operating points (openfast-runs/aero_steady/summary.csv, transcribed). Measured
  // as the pitch at which the table gives AeroDyn's Cp at the same λ, minus the run's pitch.
  const Rotor rotor;
  struct Point { double tsr, pitch_deg, cp_openfast; };
  const Point points[] = {{6.6713, 3.45, 0.41574}, {5.3370, 10.26, 0.21144}, {4.0027, 17.32, 0.08898},
                          {3.2021, 22.96, 0.04584}};
  for (const Point& x : points) {
    const double cp = rotor.power_coefficient(x.tsr, x.pitch_deg);
    const double offset_deg = fowtsim::control::verification::pitch_for_cp_deg(rotor, x.tsr, x.cp_openfast) - x.pitch_deg;
    INFO("λ = " << x.tsr << ", θ = " << x.pitch_deg << "°: table Cp " << cp << ", OpenFAST " << x.cp_openfast
                << ", pitch-equivalent offset " << offset_deg << "°");
    // CCBlade table (no skew from the 5° tilt) vs AeroDyn: Cp 1.7–8.8 % low, i.e. the table reaches
    // AeroDyn's Cp at a pitch 0.11, 0.11, 0.27, 0.46° lower (12, 15, 20, 25 m/s). Bound: the issue's
    // 0.5°, the most the test rotor may differ from AeroDyn for the operating-table check to mean
    // anything; 25 m/s is close to it (the published pitch lies between AeroDyn's rigid-rotor
    // equilibrium and this table's).
    CHECK(std::abs(offset_deg) <= 0.5);
  }
}

TEST_CASE("wind steps: pitch and torque rate limits hold, no windup", "[verification][control]") {
  // Intent: issue 6 step responses — wind 10.5 → 16 → 10.5 → 16 m/s at 100, 300 and 400 s (regions
  // 2 ↔ 3). At every update |Δθ| ≤ 8°/s Δt and |ΔT| ≤ 15 kN·m/s Δt; θ ∈ [0°, 90°], T ≤ VS_MaxTq;
  // the speed returns to rated after each step up (bounded response); after the return to region 2
  // the pitch is back at 0 and the integral term at its lower clamp, so the second step up is
  // answered exactly as the first (no windup).
  const Rotor rotor;
  const auto wind = [](double t) { return t < 100.0 ? 10.5 : t < 300.0 ? 16.0 : t < 400.0 ? 10.5 : 16.0; };
  for (const auto& [name, p] : {std::pair{"land", nrel5mw_land_baseline()}, std::pair{"OC3", oc3_hywind_baseline()}}) {
    BaselineController::State s = BaselineController::make_state(p);
    double max_pitch_rate = 0, max_torque_rate = 0, max_speed = 0, min_pitch = 1, max_pitch = -1, max_torque = 0;
    double first_response = -1, second_response = -1, pitch_before_second = -1, integral_term_before_second = -1;
    double speed_error_end_first = 0, speed_error_end_second = 0;
    LoopSample last;
    bool have_last = false;
    run_loop<BaselineController>(rotor, p, s, wind, 9.0 / kRpm, 0.0, kStep, 600.0, [&](const LoopSample& x) {
      const double pitch = x.demand.blade_pitch_rad[0];
      if (have_last) {
        const double dt = x.time_s - last.time_s;
        max_pitch_rate = std::max(max_pitch_rate, std::abs(pitch - last.demand.blade_pitch_rad[0]) / dt);
        max_torque_rate = std::max(max_torque_rate, std::abs(x.demand.generator_torque_N_m - last.demand.generator_torque_N_m) / dt);
      }
      max_speed = std::max(max_speed, x.rotor_speed_rad_s);
      min_pitch = std::min(min_pitch, pitch);
      max_pitch = std::max(max_pitch, pitch);
      max_torque = std::max(max_torque, x.demand.generator_torque_N_m);
      // Time from each step up until the pitch first exceeds 1°.
      if (x.time_s >= 100.0 && first_response < 0 && pitch > 1.0 / kDeg) first_response = x.time_s - 100.0;
      if (x.time_s >= 400.0 && second_response < 0 && pitch > 1.0 / kDeg) second_response = x.time_s - 400.0;
      if (std::abs(x.time_s - 299.9875) < 1e-9) speed_error_end_first = x.rotor_speed_rad_s * kRpm - 12.1;
      if (std::abs(x.time_s - 600.0) < 1e-9) speed_error_end_second = x.rotor_speed_rad_s * kRpm - 12.1;
      if (std::abs(x.time_s - 399.9875) < 1e-9) {
        pitch_before_second = pitch;
        const double gk = 1.0 / (1.0 + s.pitch_demand_rad[0] / p.gain_schedule_pitch_rad);
        integral_term_before_second = gk * p.integral_gain * s.speed_error_integral_rad;
      }
      last = x;
      have_last = true;
    });
    INFO(name << ": max pitch rate " << max_pitch_rate * kDeg << " °/s, max torque rate " << max_torque_rate
              << " N·m/s, peak rotor speed " << max_speed * kRpm << " rpm, pitch range [" << min_pitch * kDeg << ", "
              << max_pitch * kDeg << "]°, first/second response " << first_response << " / " << second_response
              << " s, speed error 200 s after each step up " << speed_error_end_first << " / " << speed_error_end_second
              << " rpm");
    // Rate limits (PUBLISHED.md): exact up to round-off of the differences, 1e-9 relative.
    CHECK(max_pitch_rate <= 0.1396263 * (1 + 1e-9));
    CHECK(max_torque_rate <= 15000.0 * (1 + 1e-9));
    CHECK(min_pitch >= 0.0);
    CHECK(max_pitch <= p.max_pitch_rad);
    CHECK(max_torque <= p.max_torque_N_m);
    // Bounded: back at rated speed 200 s after each step up. Measured 2.3e-6 rpm (both sets; the
    // 4e-7 rpm rounding of PC_RefSpd included); tolerance 5e-5 rpm.
    CHECK(std::abs(speed_error_end_first) <= 5e-5);
    CHECK(std::abs(speed_error_end_second) <= 5e-5);
    // No windup: pitch at 0 and the integral term at its lower clamp before the second step, and
    // the second step is answered as fast as the first (same state: both start from the settled
    // region-2 point; one step 0.0125 s of slack).
    CHECK(pitch_before_second == 0.0);
    CHECK(integral_term_before_second == 0.0);
    REQUIRE(first_response > 0.0);
    CHECK(std::abs(second_response - first_response) <= 0.0125 + 1e-9);
  }
}
