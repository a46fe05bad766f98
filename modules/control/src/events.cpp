#include "fowtsim/control/events.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::control {
namespace {

constexpr int kNoManoeuvre = 0, kToFeather = 1, kStartup = 2;
constexpr int kRunaway = 1, kStuck = 2;  // EventState::fault; 0 none

// A time event is due at the first call at or after its time; 1e-6 of a step absorbs the rounding
// of t = k Δt summed or multiplied (a deck's at_s = 10 with Δt = 0.0125 fires at k = 800, not 801).
bool time_reached(double t, double dt, double at_s) { return t + 1e-6 * dt >= at_s; }

void start_feathering(const ControllerInput& u, double t, double rate, EventState& s) {
  s.manoeuvre = kToFeather;
  s.manoeuvre_start_s = t;
  s.manoeuvre_rate_rad_s = rate;
  s.manoeuvre_from_rad = u.blade_pitch_rad;
}

void apply_brake(double t, EventState& s) {
  if (std::isnan(s.brake_engaged_at_s)) s.brake_engaged_at_s = t;
  s.brake_by_controller = false;  // an event's brake stays on whatever the controller says
}

void fire(const EventParams& e, const ControllerInput& u, double t, EventState& s) {
  switch (e.type) {
    case EventType::shutdown:
      start_feathering(u, t, e.pitch_rate_rad_s, s);
      s.generator_off_below_cut_in = s.generator_connected;
      s.connect_at_cut_in = false;
      break;
    case EventType::emergency_stop:
      start_feathering(u, t, e.pitch_rate_rad_s, s);
      s.generator_connected = s.generator_off_below_cut_in = s.connect_at_cut_in = false;
      apply_brake(t, s);
      break;
    case EventType::grid_loss:
      s.generator_connected = s.generator_off_below_cut_in = s.connect_at_cut_in = false;
      s.pending_shutdown_at_s = t + e.shutdown_delay_s;
      s.pending_shutdown_rate_rad_s = e.pitch_rate_rad_s;
      break;
    case EventType::brake:
      apply_brake(t, s);
      break;
    case EventType::pitch_runaway: {
      const auto b = static_cast<std::size_t>(e.blade);
      s.fault[b] = kRunaway;
      s.fault_start_s[b] = t;
      s.fault_from_rad[b] = u.blade_pitch_rad[b];
      s.fault_target_rad[b] = e.target_pitch_rad;
      s.fault_rate_rad_s[b] = e.pitch_rate_rad_s;
      break;
    }
    case EventType::pitch_stuck: {
      const auto b = static_cast<std::size_t>(e.blade);
      s.fault[b] = kStuck;
      s.fault_from_rad[b] = u.blade_pitch_rad[b];
      break;
    }
    case EventType::startup:
      s.brake_engaged_at_s = EventState::kNever;
      s.brake_by_controller = false;
      s.manoeuvre = kStartup;
      s.manoeuvre_start_s = t;
      s.manoeuvre_rate_rad_s = e.pitch_rate_rad_s;
      s.manoeuvre_from_rad = u.blade_pitch_rad;
      s.pending_shutdown_at_s = EventState::kNever;
      s.generator_off_below_cut_in = false;
      s.connect_at_cut_in = !s.generator_connected;
      break;
  }
}

double channel_value(TriggerChannel c, const ControllerInput& u) {
  return c == TriggerChannel::generator_speed ? u.generator_speed_rad_s : u.rotor_speed_rad_s;
}

}  // namespace

OperatingMode operating_mode_from_name(const std::string& name) {
  if (name == "idling") return OperatingMode::idling;
  if (name == "parked") return OperatingMode::parked;
  return OperatingMode::operating;
}

EventType event_type_from_name(const std::string& name) {
  for (const EventType t : {EventType::shutdown, EventType::emergency_stop, EventType::grid_loss, EventType::brake,
                            EventType::pitch_runaway, EventType::pitch_stuck, EventType::startup})
    if (name == event_type_name(t)) return t;
  throw InputError({"control", std::nullopt, "controller.events.type", "a known event type"}, "unknown event type '" + name + "'");
}

TriggerChannel trigger_channel_from_name(const std::string& name) {
  return name == "RotSpeed" ? TriggerChannel::rotor_speed : TriggerChannel::generator_speed;
}

const char* event_type_name(EventType type) {
  switch (type) {
    case EventType::shutdown: return "shutdown";
    case EventType::emergency_stop: return "emergency_stop";
    case EventType::grid_loss: return "grid_loss";
    case EventType::brake: return "brake";
    case EventType::pitch_runaway: return "pitch_runaway";
    case EventType::pitch_stuck: return "pitch_stuck";
    case EventType::startup: return "startup";
  }
  return "?";
}

void validate(const EventsParams& p) {
  std::string problems;
  const auto require = [&](bool ok, const std::string& key, const std::string& what) {
    if (!ok) problems += fmt::format("\n  controller.{}: {}", key, what);
  };
  require(p.events.size() <= kMaxEvents, "events", fmt::format("expected at most {} events, found {}", kMaxEvents, p.events.size()));
  require(std::isfinite(p.brake.torque_N_m) && p.brake.torque_N_m >= 0.0, "brake.torque_N_m", "expected a finite value >= 0");
  require(std::isfinite(p.brake.engage_time_s) && p.brake.engage_time_s >= 0.0, "brake.engage_time_s", "expected a finite value >= 0");
  for (std::size_t i = 0; i < p.events.size(); ++i) {
    const EventParams& e = p.events[i];
    const std::string k = fmt::format("events[{}]", i);
    require(std::isfinite(e.pitch_rate_rad_s) && e.pitch_rate_rad_s > 0.0, k + ".pitch_rate_deg_s", "expected a value > 0");
    require(e.blade >= 0 && e.blade < kBladeCount, k + ".blade", fmt::format("expected 1..{}", kBladeCount));
    require(std::isfinite(e.at_s) && std::isfinite(e.above), k, "expected a finite time or threshold");
    require(std::isfinite(e.shutdown_delay_s) && e.shutdown_delay_s >= 0.0, k + ".shutdown_delay_s", "expected a value >= 0");
    require(std::isfinite(e.target_pitch_rad), k + ".target_deg", "expected a finite value");
  }
  if (!problems.empty())
    throw InputError({"control", std::nullopt, "controller.events", "fix the listed keys"}, "invalid control events:" + problems);
}

double brake_torque_N_m(const BrakeParams& p, double engaged_at_s, double t) {
  if (std::isnan(engaged_at_s) || t < engaged_at_s) return 0.0;
  // HSSBrMode 1: linear ramp over HSSBrDT, then the full torque (an engage time of 0: at once).
  const double elapsed = t - engaged_at_s;
  return elapsed >= p.engage_time_s ? p.torque_N_m : p.torque_N_m * elapsed / p.engage_time_s;
}

EventState make_event_state(const EventsParams& p) {
  EventState s;
  s.fired_at_s.fill(EventState::kNever);
  if (p.mode != OperatingMode::operating) {
    s.generator_connected = false;
    s.manoeuvre = kToFeather;  // a ramp from feather to feather: held there (any rate > 0 does)
    s.manoeuvre_from_rad.fill(p.feather_pitch_rad);
    s.manoeuvre_rate_rad_s = 1.0;
  }
  // Parked: the brake fully deployed from the start (engaged one engage time before t = 0).
  if (p.mode == OperatingMode::parked) s.brake_engaged_at_s = -p.brake.engage_time_s;
  return s;
}

void event_status(const EventState& s, ControllerInput& u) {
  u.generator_contactor = s.generator_connected ? 1 : 0;
  u.shaft_brake = std::isnan(s.brake_engaged_at_s) ? 0 : 1;
}

double pitch_ramp(double from, double to, double rate, double elapsed) {
  const double moved = rate * elapsed;
  return from < to ? std::min(to, from + moved) : std::max(to, from - moved);
}

void apply_events(const EventsParams& p, const ControllerInput& u, double t, double dt, EventState& s, ControllerOutput& y) {
  s.started = true;
  for (std::size_t i = 0; i < p.events.size(); ++i) {
    if (!std::isnan(s.fired_at_s[i])) continue;
    const EventParams& e = p.events[i];
    const bool due = e.channel == TriggerChannel::time ? time_reached(t, dt, e.at_s) : channel_value(e.channel, u) > e.above;
    if (!due) continue;
    s.fired_at_s[i] = t;
    fire(e, u, t, s);
  }
  if (!std::isnan(s.pending_shutdown_at_s) && time_reached(t, dt, s.pending_shutdown_at_s)) {
    start_feathering(u, t, s.pending_shutdown_rate_rad_s, s);
    s.pending_shutdown_at_s = EventState::kNever;
  }
  if (s.generator_off_below_cut_in && u.generator_speed_rad_s < p.cut_in_speed_rad_s) {
    s.generator_connected = false;
    s.generator_off_below_cut_in = false;
  }
  if (s.connect_at_cut_in && u.generator_speed_rad_s >= p.cut_in_speed_rad_s) {
    s.generator_connected = true;
    s.connect_at_cut_in = false;
  }
  // The law's own requests (a DISCON's records 35 and 36): its brake is on while it asks.
  if (y.shaft_brake != 0 && std::isnan(s.brake_engaged_at_s)) {
    s.brake_engaged_at_s = t;
    s.brake_by_controller = true;
  } else if (y.shaft_brake == 0 && s.brake_by_controller) {
    s.brake_engaged_at_s = EventState::kNever;
    s.brake_by_controller = false;
  }
  const bool generator_on = s.generator_connected && y.generator_contactor != 0;
  if (!generator_on) {
    y.generator_torque_N_m = 0.0;
    y.generator_power_W = 0.0;
  }
  y.generator_contactor = generator_on ? 1 : 0;
  y.shaft_brake = std::isnan(s.brake_engaged_at_s) ? 0 : 1;

  const double elapsed = t - s.manoeuvre_start_s;
  bool startup_ramp_above_law = false;
  for (std::size_t b = 0; b < kBladeCount; ++b) {
    double& theta = y.blade_pitch_rad[b];
    if (s.manoeuvre == kToFeather) {
      theta = pitch_ramp(s.manoeuvre_from_rad[b], p.feather_pitch_rad, s.manoeuvre_rate_rad_s, elapsed);
    } else if (s.manoeuvre == kStartup) {
      const double ramp = s.manoeuvre_from_rad[b] - s.manoeuvre_rate_rad_s * elapsed;
      if (ramp > theta) {
        theta = ramp;
        startup_ramp_above_law = true;
      }
    }
    if (s.fault[b] == kRunaway)
      theta = pitch_ramp(s.fault_from_rad[b], s.fault_target_rad[b], s.fault_rate_rad_s[b], t - s.fault_start_s[b]);
    else if (s.fault[b] == kStuck)
      theta = s.fault_from_rad[b];
  }
  // The start-up ramp has met the law's demand on every blade: the law is in charge from here.
  if (s.manoeuvre == kStartup && !startup_ramp_above_law) s.manoeuvre = kNoManoeuvre;
}

}  // namespace fowtsim::control
