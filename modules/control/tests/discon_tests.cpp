// The Bladed-style DLL interface against the built-in controller: the test DISCON library
// (tests/discon/test_discon.cpp) runs the same baseline law behind the float32 swap array.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/control/baseline_controller.hpp"
#include "fowtsim/control/external_controller.hpp"
#include "fowtsim/control/presets.hpp"
#include "fowtsim/control/swap_records.hpp"
#include "fowtsim/control/verification.hpp"
#include "fowtsim/core/error.hpp"

using namespace fowtsim;
using namespace fowtsim::control;
using fowtsim::control::verification::LoopSample;
using fowtsim::control::verification::Rotor;
using fowtsim::control::verification::run_loop;

namespace {

ExternalSettings test_discon(const std::string& infile, bool individual_pitch = false) {
  ExternalSettings e;
  e.library_path = FOWTSIM_TEST_DISCON;
  e.infile = infile;
  e.outname = "discon_test";
  e.individual_pitch = individual_pitch;
  return e;
}

ControllerInput sweep_input(double t, const ControllerOutput& last) {
  ControllerInput u;
  u.generator_speed_rad_s = 116.0 + 16.0 * std::sin(2.0 * std::numbers::pi * t / 40.0);  // regions 2, 2½, 3
  u.rotor_speed_rad_s = u.generator_speed_rad_s / 97.0;
  u.blade_pitch_rad = last.blade_pitch_rad;
  u.hub_wind_speed_m_s = 11.0;
  return u;
}

}  // namespace

TEST_CASE("DLL interface reproduces the built-in controller's time series", "[verification][control]") {
  // Intent: issue 6 — the same law through the swap array gives the same torque and pitch series
  // as the built-in controller, to float32 precision (not bit-identical: records are single
  // precision, including the time, so Δt inside the DLL carries the float rounding of t).
  // Open loop in speed (a sweep through regions 2–3 over 100 s at the OC3 step 0.0125 s), each
  // controller's own previous pitch demand fed back as the measured pitch; both blade modes.
  for (const auto& [set, individual] : {std::pair{"nrel5mw_land", false}, std::pair{"nrel5mw_land", true},
                                        std::pair{"oc3_hywind", false}}) {
    const BaselineParams p = *baseline_preset(set);
    const ExternalController::Params ep = ExternalController::make_params(test_discon(set, individual));
    ExternalController::State es = ExternalController::make_state(ep);
    BaselineController::State bs = BaselineController::make_state(p);
    ControllerOutput ey, by;
    double max_torque_diff = 0.0, max_pitch_diff = 0.0, max_torque = 0.0, max_pitch = 0.0;
    const double dt = 0.0125;
    for (int k = 0; k <= 8000; ++k) {
      const double t = k * dt;
      const ControllerInput eu = sweep_input(t, ey), bu = sweep_input(t, by);
      ExternalController::advance(ep, eu, t, dt, es);
      BaselineController::advance(p, bu, t, dt, bs);
      ey = ExternalController::outputs(ep, eu, es);
      by = BaselineController::outputs(p, bu, bs);
      max_torque_diff = std::max(max_torque_diff, std::abs(ey.generator_torque_N_m - by.generator_torque_N_m));
      max_torque = std::max(max_torque, by.generator_torque_N_m);
      for (int b = 0; b < kBladeCount; ++b) {
        max_pitch_diff = std::max(max_pitch_diff, std::abs(ey.blade_pitch_rad[b] - by.blade_pitch_rad[b]));
      }
      max_pitch = std::max(max_pitch, by.blade_pitch_rad[0]);
    }
    ExternalController::finish(ep, 100.0, es);
    INFO(set << ", individual pitch " << individual << ": max |ΔT| = " << max_torque_diff << " N·m (of " << max_torque
                             << "), max |Δθ| = " << max_pitch_diff << " rad (of " << max_pitch << ")");
    REQUIRE(max_pitch > 0.05);  // the sweep reached region 3 and pitched
    // float32 precision, not bit-identical. Record 2 (time) is single precision: ulp(t) ≤ 7.6e-6 s
    // for t ≤ 100 s, which perturbs the Δt of the DLL's filter step by up to 6e-4 relative; the
    // 2½ slope (3,935 N·m/(rad/s)) turns that into torque. Measured max |ΔT| 0.058 (land) and
    // 0.099 N·m (OC3); tolerance 1 N·m (2e-5 relative). Pitch: measured 4.6e-7 rad; tolerance 5e-6 rad.
    CHECK(max_torque_diff <= 1.0);
    CHECK(max_pitch_diff <= 5e-6);
  }
}

TEST_CASE("DLL interface in closed loop with the rotor", "[verification][control]") {
  // Intent: the DLL path closes the loop with the rotor like the built-in one: OC3 set, wind
  // 13 → 15 m/s at 30 s, 200 s; the two pitch series agree to float32 precision.
  const Rotor rotor;
  const BaselineParams p = oc3_hywind_baseline();
  const ExternalController::Params ep = ExternalController::make_params(test_discon("oc3_hywind"));
  ExternalController::State es = ExternalController::make_state(ep);
  BaselineController::State bs = BaselineController::make_state(p);
  double pitch_dll = 0, pitch_builtin = 0, max_diff = 0;
  std::vector<double> builtin;
  const auto wind = [](double t) { return t < 30.0 ? 13.0 : 15.0; };
  run_loop<BaselineController>(rotor, p, bs, wind, 12.1 * std::numbers::pi / 30.0, 0.0, 0.0125, 200.0,
                               [&](const LoopSample& x) { builtin.push_back(x.demand.blade_pitch_rad[0]); });
  std::size_t k = 0;
  run_loop<ExternalController>(rotor, ep, es, wind, 12.1 * std::numbers::pi / 30.0, 0.0, 0.0125, 200.0,
                               [&](const LoopSample& x) {
                                 max_diff = std::max(max_diff, std::abs(x.demand.blade_pitch_rad[0] - builtin[k]));
                                 pitch_dll = x.demand.blade_pitch_rad[0];
                                 pitch_builtin = builtin[k++];
                               });
  ExternalController::finish(ep, 200.0, es);
  INFO("final pitch DLL " << pitch_dll << " rad, built-in " << pitch_builtin << " rad; max |Δθ| " << max_diff << " rad");
  // float32 swap records in a stable loop: measured max 3.3e-8 rad; tolerance 5e-7 rad.
  CHECK(max_diff <= 5e-7);
}

TEST_CASE("swap records sent to the DLL", "[unit][control]") {
  // Intent: the documented records (swap_records.hpp) carry the measurements and settings.
  const ExternalController::Params ep = ExternalController::make_params(test_discon("oc3_hywind"));
  ExternalController::State s = ExternalController::make_state(ep);
  ControllerInput u;
  u.generator_speed_rad_s = 100.0;
  u.rotor_speed_rad_s = 100.0 / 97.0;
  u.blade_pitch_rad = {0.01, 0.02, 0.03};
  u.hub_wind_speed_m_s = 9.5;
  ExternalController::advance(ep, u, 2.5, 0.0125, s);
  ExternalController::advance(ep, u, 2.5125, 0.0125, s);
  const auto rec = [&](int r) { return static_cast<double>(s.swap[r - 1]); };
  CHECK(rec(swap::status) == 1.0);
  CHECK(rec(swap::time) == static_cast<float>(2.5125));
  CHECK(rec(swap::communication_interval) == static_cast<float>(0.0125));
  CHECK(rec(swap::blade1_pitch) == static_cast<float>(0.01));
  CHECK(rec(swap::blade2_pitch) == static_cast<float>(0.02));
  CHECK(rec(swap::blade3_pitch) == static_cast<float>(0.03));
  CHECK(rec(swap::generator_speed) == 100.0f);
  CHECK(rec(swap::rotor_speed) == static_cast<float>(100.0 / 97.0));
  CHECK(rec(swap::hub_wind_speed) == 9.5f);
  CHECK(rec(swap::max_pitch_rate) == static_cast<float>(0.1396263));
  CHECK(rec(swap::min_pitch_rate) == static_cast<float>(-0.1396263));
  CHECK(rec(swap::pitch_control_mode) == 0.0);
  CHECK(rec(swap::infile_length) == std::string("oc3_hywind").size() + 1);
  CHECK(rec(swap::blade_count) == 3.0);
  CHECK(rec(swap::swap_size) == kSwapSize);
  // Region 2 at 100 rad/s: the DLL's torque demand is read from record 47.
  CHECK(ExternalController::outputs(ep, u, s).generator_torque_N_m == static_cast<double>(s.swap[swap::generator_torque_demand - 1]));
  ExternalController::finish(ep, 2.525, s);
  CHECK(rec(swap::status) == -1.0);
}

TEST_CASE("DLL errors: missing library, missing procedure, aviFAIL < 0", "[unit][control]") {
  // Intent: issue 6 robustness — a clear InputError naming the path before the run; a controller
  // that rejects its input at its first call is bad input too (issue 16: exit 2, not 3), carrying
  // its message.
  ExternalSettings missing = test_discon("oc3_hywind");
  missing.library_path = "/nonexistent/libno_discon.so";
  try {
    ExternalController::make_params(missing);
    FAIL("no InputError for a missing library");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains("/nonexistent/libno_discon.so"));
  }
  ExternalSettings no_symbol = test_discon("oc3_hywind");
  no_symbol.procedure = "NOT_DISCON";
  try {
    ExternalController::make_params(no_symbol);
    FAIL("no InputError for a missing procedure");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains(FOWTSIM_TEST_DISCON) && Catch::Contains("NOT_DISCON"));
  }
  const ExternalController::Params ep = ExternalController::make_params(test_discon("no_such_set"));
  ExternalController::State s = ExternalController::make_state(ep);
  ControllerInput u;
  u.generator_speed_rad_s = 100.0;
  try {
    ExternalController::advance(ep, u, 0.0, 0.0125, s);
    FAIL("no InputError for aviFAIL < 0 at the first call");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains("unknown parameter set 'no_such_set'"));
    CHECK(e.context().variable == "aviFAIL");
    REQUIRE(e.context().time_s.has_value());
    CHECK(*e.context().time_s == 0.0);
  }
}

TEST_CASE("DLL records 55 and 56: a request for the simulator's built-in override stops the run at its time", "[unit][control]") {
  // Intent: Bladed's pitch/torque override records are read, not ignored: like ServoDyn, any value
  // but 0 is refused — with the record, the time of the call and the library in the message.
  for (const auto& [suffix, record] : {std::pair{"+pitch_override", 55}, std::pair{"+torque_override", 56}}) {
    const ExternalController::Params ep = ExternalController::make_params(test_discon(std::string("oc3_hywind") + suffix));
    ExternalController::State s = ExternalController::make_state(ep);
    ControllerInput u;
    u.generator_speed_rad_s = 100.0;
    const double dt = 0.25;
    double t = 0.0;
    try {
      for (; t < 3.0; t += dt) ExternalController::advance(ep, u, t, dt, s);
      FAIL("no NumericalError for record " << record << " = 1");
    } catch (const NumericalError& e) {
      CHECK(e.context().variable == "avrSWAP record " + std::to_string(record));
      REQUIRE(e.context().time_s.has_value());
      CHECK(*e.context().time_s == 1.0);  // the test DISCON asks from t = 1 s: the first call at or after it
      CHECK_THAT(e.what(), Catch::Contains(record == 55 ? "pitch override" : "torque override"));
    }
  }
}
