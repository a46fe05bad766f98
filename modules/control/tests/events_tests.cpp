// Control and fault events (events.hpp) on the built-in law and on the test DISCON: pitch
// manoeuvres against their closed-form ramps, the generator's contactor, the brake's HSSBrMode-1
// ramp, blade faults, the initial modes, and the Bladed records 35/36 both ways.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <catch2/catch.hpp>

#include "fowtsim/control/baseline_controller.hpp"
#include "fowtsim/control/events.hpp"
#include "fowtsim/control/external_controller.hpp"
#include "fowtsim/control/presets.hpp"
#include "fowtsim/control/swap_records.hpp"

using namespace fowtsim::control;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kDt = 0.0125;  // the OC3 large step [s]

// The law and the events as the driver's TurbineController runs them (status → law → events), with
// an ideal pitch actuator (each blade's measured pitch is its last demand) and a prescribed
// generator speed speed(t).
template <class Speed>
struct Loop {
  BaselineParams law = nrel5mw_land_baseline();
  EventsParams events;
  BaselineState s{};
  EventState e{};
  ControllerOutput y{};
  ControllerInput u{};
  Speed speed;

  explicit Loop(Speed sp, double initial_pitch_rad) : speed(sp) { u.blade_pitch_rad.fill(initial_pitch_rad); }
  void start() {
    s = BaselineController::make_state(law);
    e = make_event_state(events);
  }
  void call(double t) {
    u.generator_speed_rad_s = speed(t);
    u.rotor_speed_rad_s = speed(t) / 97.0;
    event_status(e, u);
    BaselineController::advance(law, u, t, kDt, s);
    y = BaselineController::outputs(law, u, s);
    apply_events(events, u, t, kDt, e, y);
    u.blade_pitch_rad = y.blade_pitch_rad;
  }
};

EventParams at(EventType type, double t_s, double rate_deg_s = 8.0) {
  EventParams p;
  p.type = type;
  p.at_s = t_s;
  p.pitch_rate_rad_s = rate_deg_s * kDeg;
  return p;
}

}  // namespace

TEST_CASE("shutdown: every blade feathers at the rate exactly; the generator opens below cut-in", "[verification][control]") {
  // Intent: the pitch-to-feather manoeuvre (ServoDyn TPitManS/PitManRat/BlPitchF) in closed form
  // θ(t_k) = θ₀ + r (t_k − t_fire) until 90°, whatever the law demands; the generator keeps the
  // law's torque until the generator speed falls below VS_CtInSp, then stays off.
  auto speed = [](double t) { return t < 20.0 ? 125.0 : 60.0; };  // above rated, then below cut-in
  Loop<decltype(speed)> loop(speed, 5.0 * kDeg);
  loop.events.events = {at(EventType::shutdown, 10.0)};
  loop.start();
  double theta0 = 0.0, worst = 0.0;
  bool reached_feather = false;
  for (int k = 0; k <= 2400; ++k) {
    const double t = k * kDt;
    const double before = loop.u.blade_pitch_rad[0];
    loop.call(t);
    if (k == 800) theta0 = before;  // t = 10 s: fires at this call from the pitch the blades have
    if (k >= 800) {
      const double expected = std::min(loop.events.feather_pitch_rad, theta0 + 8.0 * kDeg * (t - 10.0));
      for (double th : loop.y.blade_pitch_rad) worst = std::max(worst, std::abs(th - expected));
      reached_feather = reached_feather || loop.y.blade_pitch_rad[0] == loop.events.feather_pitch_rad;
    }
    if (k > 800 && t < 20.0) CHECK(loop.y.generator_torque_N_m > 0.0);  // still on above cut-in
    if (t >= 20.0) CHECK(loop.y.generator_torque_N_m == 0.0);
  }
  CHECK(std::isfinite(loop.e.fired_at_s[0]));
  CHECK(loop.e.fired_at_s[0] == 800 * kDt);
  CHECK(theta0 > 0.0);
  // 1e-14 rad: θ₀ + r Δt rounded once (|θ| ≤ 1.6 rad, ulp 2.2e-16); measured 0 (the same expression).
  CHECK(worst <= 1e-14);
  CHECK(reached_feather);
  CHECK(loop.y.generator_contactor == 0);
}

TEST_CASE("emergency stop and grid loss: generator off at once, brake ramp, delayed feathering", "[verification][control]") {
  // Intent: emergency_stop opens the contactor at once and applies the HSS brake with ServoDyn's
  // HSSBrMode 1 ramp (HSSBrTqF (t − THSSBrDp)/HSSBrDT); grid_loss opens it at once and starts the
  // feathering shutdown_delay_s later, the law's pitch in between.
  auto speed = [](double) { return 125.0; };
  {
    Loop<decltype(speed)> loop(speed, 5.0 * kDeg);
    loop.events.events = {at(EventType::emergency_stop, 1.0, 10.0)};
    loop.start();
    for (int k = 0; k <= 400; ++k) {
      loop.call(k * kDt);
      if (k >= 80) CHECK(loop.y.generator_torque_N_m == 0.0);
      if (k == 79) CHECK(loop.y.generator_torque_N_m > 0.0);
    }
    const BrakeParams& b = loop.events.brake;
    CHECK(loop.e.brake_engaged_at_s == 1.0);
    // Exact ramp points (one product and one division: 1e-12 relative).
    CHECK(brake_torque_N_m(b, 1.0, 1.0) == 0.0);
    CHECK(brake_torque_N_m(b, 1.0, 1.3) == Approx(0.5 * 28116.2).epsilon(1e-12));
    CHECK(brake_torque_N_m(b, 1.0, 1.6) == 28116.2);
    CHECK(brake_torque_N_m(b, 1.0, 7.0) == 28116.2);
    CHECK(brake_torque_N_m(b, EventState::kNever, 7.0) == 0.0);
    CHECK(loop.y.shaft_brake == 1);
  }
  {
    Loop<decltype(speed)> loop(speed, 5.0 * kDeg);
    EventParams loss = at(EventType::grid_loss, 1.0);
    loss.shutdown_delay_s = 0.5;
    loop.events.events = {loss};
    loop.start();
    double theta_start = 0.0;
    for (int k = 0; k <= 400; ++k) {
      const double t = k * kDt;
      const double before = loop.u.blade_pitch_rad[0];
      loop.call(t);
      if (k >= 80) CHECK(loop.y.generator_torque_N_m == 0.0);
      if (k == 120) theta_start = before;  // 1.5 s: the manoeuvre starts from the law's pitch
      if (k >= 120)
        CHECK(std::abs(loop.y.blade_pitch_rad[1] - std::min(loop.events.feather_pitch_rad, theta_start + 8.0 * kDeg * (t - 1.5))) <= 1e-14);
    }
    CHECK(loop.y.generator_contactor == 0);
    CHECK(loop.y.shaft_brake == 0);
  }
}

TEST_CASE("pitch faults: a stuck blade stays put, a runaway blade ramps to fine pitch, the others follow", "[verification][control]") {
  // Intent: issue 27 — the faulty blade's pitch is held (stuck) or ramps at its rate to the target
  // (runaway), bit-exactly, while the healthy blades keep following the law (and a shutdown).
  auto speed = [](double t) { return 125.0 + 10.0 * std::sin(0.3 * t); };  // region 3: the law keeps pitching
  Loop<decltype(speed)> loop(speed, 10.0 * kDeg);
  EventParams stuck = at(EventType::pitch_stuck, 2.0);
  stuck.blade = 1;
  EventParams runaway = at(EventType::pitch_runaway, 4.0, 2.0);
  runaway.blade = 2;
  runaway.target_pitch_rad = 0.0;
  loop.events.events = {stuck, runaway, at(EventType::shutdown, 20.0)};
  loop.start();
  double stuck_at = 0.0, runaway_from = 0.0, healthy_min = 1e9, healthy_max = -1e9;
  for (int k = 0; k <= 2400; ++k) {
    const double t = k * kDt;
    const ControllerInput before = loop.u;
    loop.call(t);
    if (k == 160) stuck_at = before.blade_pitch_rad[1];
    if (k == 320) runaway_from = before.blade_pitch_rad[2];
    if (k >= 160) CHECK(loop.y.blade_pitch_rad[1] == stuck_at);  // exact: held, not recomputed
    if (k >= 320)
      CHECK(std::abs(loop.y.blade_pitch_rad[2] - std::max(0.0, runaway_from - 2.0 * kDeg * (t - 4.0))) <= 1e-14);
    if (k >= 160) {
      healthy_min = std::min(healthy_min, loop.y.blade_pitch_rad[0]);
      healthy_max = std::max(healthy_max, loop.y.blade_pitch_rad[0]);
    }
  }
  CHECK(healthy_max - healthy_min > 30.0 * kDeg);  // blade 1 moved (law, then feathering to 90°)
  CHECK(loop.y.blade_pitch_rad[0] == loop.events.feather_pitch_rad);
  CHECK(loop.y.blade_pitch_rad[1] == stuck_at);  // a stuck blade does not feather
  CHECK(loop.y.blade_pitch_rad[2] == 0.0);       // the runaway blade stays at its target
}

TEST_CASE("a condition fires once, the first call it holds", "[unit][control]") {
  // Intent: `when: {channel: GenSpeed, above: …}` — an overspeed trip after a grid loss.
  auto speed = [](double t) { return 120.0 + 2.0 * t; };  // crosses 140 rad/s at t = 10 s
  Loop<decltype(speed)> loop(speed, 0.0);
  EventParams trip;
  trip.type = EventType::emergency_stop;
  trip.channel = TriggerChannel::generator_speed;
  trip.above = 140.0;
  trip.pitch_rate_rad_s = 8.0 * kDeg;
  loop.events.events = {at(EventType::grid_loss, 1.0), trip};
  loop.start();
  for (int k = 0; k <= 1200; ++k) loop.call(k * kDt);
  // The first call with 120 + 2 t > 140: t = 10.0125 s (k = 801; at k = 800 the speed is exactly 140).
  CHECK(loop.e.fired_at_s[1] == 801 * kDt);
  CHECK(loop.e.brake_engaged_at_s == 801 * kDt);
}

TEST_CASE("idling, parked and start-up", "[verification][control]") {
  // Intent: idling — pitch at feather, no torque; parked — the brake fully on from t = 0; start-up —
  // the brake released, each blade from feather down at the rate until it meets the law's demand,
  // the generator connected once the speed reaches VS_CtInSp (70.16224 rad/s).
  auto speed = [](double t) { return std::min(100.0, 5.0 * t); };
  Loop<decltype(speed)> loop(speed, 90.0 * kDeg);
  loop.events.mode = OperatingMode::parked;
  loop.events.events = {at(EventType::startup, 5.0, 2.0)};
  loop.start();
  CHECK(brake_torque_N_m(loop.events.brake, loop.e.brake_engaged_at_s, 0.0) == 28116.2);
  bool law_took_over = false;
  for (int k = 0; k <= 4800; ++k) {
    const double t = k * kDt;
    loop.call(t);
    if (t < 5.0 - 1e-9) {
      for (double th : loop.y.blade_pitch_rad) CHECK(th == loop.events.feather_pitch_rad);
      CHECK(loop.y.generator_torque_N_m == 0.0);
      CHECK(loop.y.shaft_brake == 1);
    } else {
      CHECK(loop.y.shaft_brake == 0);
      const double ramp = loop.events.feather_pitch_rad - 2.0 * kDeg * (t - 5.0);
      // Never below the ramp while it lasts (the larger of the ramp and the law's demand).
      if (!law_took_over) CHECK(loop.y.blade_pitch_rad[0] >= ramp - 1e-14);
      if (loop.e.manoeuvre == 0) law_took_over = true;
      if (speed(t) < 70.16224) CHECK(loop.y.generator_torque_N_m == 0.0);
    }
  }
  CHECK(law_took_over);
  CHECK(loop.e.generator_connected);
  CHECK(loop.y.generator_torque_N_m > 0.0);
}

TEST_CASE("DISCON: the turbine's contactor and brake go out in records 35/36, the library's requests come back", "[unit][control]") {
  // Intent: Bladed records 35 (generator contactor) and 36 (shaft brake status) both ways: the test
  // DISCON echoes what it received into logging records 165/166; with "+trip" it opens its contactor
  // and applies the brake above 130 rad/s, which the events then carry out (torque 0, brake on).
  ExternalSettings settings;
  settings.library_path = FOWTSIM_TEST_DISCON;
  settings.infile = "oc3_hywind+trip";
  const ExternalController::Params p = ExternalController::make_params(settings);
  ExternalController::State s = ExternalController::make_state(p);
  EventsParams events;
  events.events = {at(EventType::grid_loss, 1.0)};
  EventState e = make_event_state(events);
  ControllerInput u;
  ControllerOutput y;
  double first_brake = -1.0;
  for (int k = 0; k <= 400; ++k) {
    const double t = k * kDt;
    u.generator_speed_rad_s = t < 3.0 ? 120.0 : 135.0;
    event_status(e, u);
    ExternalController::advance(p, u, t, kDt, s);
    const float received_contactor = s.swap[kLoggingStart - 1], received_brake = s.swap[kLoggingStart];
    // The call at t sees the contactor as the events left it after the call before.
    CHECK(received_contactor == (k <= 80 ? 1.0f : 0.0f));
    CHECK(received_brake == (t <= 3.0 ? 0.0f : 1.0f));
    y = ExternalController::outputs(p, u, s);
    apply_events(events, u, t, kDt, e, y);
    u.blade_pitch_rad = y.blade_pitch_rad;
    if (first_brake < 0.0 && y.shaft_brake == 1) first_brake = t;
    if (t >= 1.0) CHECK(y.generator_torque_N_m == 0.0);
  }
  CHECK(first_brake == 240 * kDt);  // the library's trip at the first call above 130 rad/s (t = 3 s)
  CHECK(e.brake_by_controller);
  ExternalController::finish(p, 400 * kDt, s);
}
