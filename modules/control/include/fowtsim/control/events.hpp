#pragma once
// Control and fault events (issue 27): the supervisory layer between a controller's law (the
// built-in baseline law or a DISCON library) and the turbine. It runs at the controller's large
// step, sample and hold, after the law: at each call it fires the events whose time has come or
// whose condition holds, then overrides the law's demands where an event says so.
//
// What the events do (the ServoDyn inputs each one stands for in brackets, OpenFAST
// docs/source/user/servodyn/input.rst):
//   shutdown        every blade pitches from where it is to feather at a constant rate [TPitManS,
//                   PitManRat, BlPitchF]; the generator stays on the law's torque until the generator
//                   speed falls below the law's cut-in speed (VS_CtInSp), then its contactor opens
//                   [TimGenOf at that moment]: the generator helps to slow the rotor, as on a
//                   variable-speed turbine that keeps its converter during a normal stop.
//   emergency_stop  the same pitch manoeuvre, the generator off at once and the high-speed-shaft
//                   brake applied at once (its torque ramps, see brake_torque_N_m).
//   grid_loss       the generator off at once (no electrical torque); after shutdown_delay_s the
//                   pitch manoeuvre of a shutdown.
//   brake           the HSS brake applied [HSSBrMode 1, THSSBrDp].
//   pitch_runaway   one blade's pitch goes at a constant rate to a target (default the minimum
//                   pitch: a runaway to fine pitch), whatever the law or a shutdown demand.
//   pitch_stuck     one blade keeps the pitch it has when the event fires.
//   startup         from idling or parked: the brake released, every blade from where it is towards
//                   the law's demand at a constant rate (the demand is the larger of the two, so the
//                   law takes over where they meet), the generator connected once the generator
//                   speed reaches the law's cut-in speed.
// Operating modes at t = 0: operating (the law in charge), idling (pitch at feather, generator off,
// rotor free), parked (idling with the brake fully applied: the rotor held).
//
// A blade fault wins over a manoeuvre on its blade (a stuck blade cannot feather). All state lives
// in EventState (plain, trivially copyable: a copy continues bit-identically; checkpointed).
#include <array>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "fowtsim/control/baseline_controller.hpp"

namespace fowtsim::control {

enum class OperatingMode { operating, idling, parked };
enum class EventType { shutdown, emergency_stop, grid_loss, brake, pitch_runaway, pitch_stuck, startup };
enum class TriggerChannel { time, generator_speed, rotor_speed };

OperatingMode operating_mode_from_name(const std::string& name);
EventType event_type_from_name(const std::string& name);
TriggerChannel trigger_channel_from_name(const std::string& name);  // GenSpeed | RotSpeed
const char* event_type_name(EventType type);

inline constexpr std::size_t kMaxEvents = 16;  // events per run (fixed-size state, no allocation)

struct EventParams {
  EventType type = EventType::shutdown;
  TriggerChannel channel = TriggerChannel::time;   // time: at_s; otherwise the first call with channel > above
  double at_s = 0.0;                               // [s] (channel time)
  double above = 0.0;                              // threshold in SI: generator or rotor speed [rad/s]
  double pitch_rate_rad_s = 0.0;                   // manoeuvre or runaway rate, > 0 [rad/s]
  int blade = 0;                                   // 0-based blade of a pitch fault
  double target_pitch_rad = 0.0;                   // pitch_runaway's end pitch [rad]
  double shutdown_delay_s = 0.2;                   // grid_loss: loss → shutdown manoeuvre [s]
};

// ServoDyn's HSS brake, HSSBrMode 1: the torque ramps linearly from 0 at the engagement time
// (THSSBrDp) to HSSBrTqF over HSSBrDT. NREL 5MW ServoDyn deck (r-test 5MW_OC3Spar_DLL_WTurb_WavesIrr):
// HSSBrTqF 28116.2 N·m, HSSBrDT 0.6 s.
struct BrakeParams {
  double torque_N_m = 28116.2;    // HSSBrTqF: fully deployed brake torque on the HSS [N·m]
  double engage_time_s = 0.6;     // HSSBrDT: time to deploy it fully [s]
};

struct EventsParams {
  OperatingMode mode = OperatingMode::operating;
  std::vector<EventParams> events;  // at most kMaxEvents
  BrakeParams brake;
  double feather_pitch_rad = 1.570796;     // shutdown target and idling pitch: the law's maximum pitch [rad]
  double cut_in_speed_rad_s = 70.16224;    // generator (dis)connection speed, HSS: the law's VS_CtInSp [rad/s]
};

// InputError naming controller.<key> for a bad value (rates ≤ 0, blade outside 1–3, too many events…).
void validate(const EventsParams& p);

// The brake torque at time t of a brake engaged at `engaged_at_s` (NaN: released) [N·m, HSS, ≥ 0].
double brake_torque_N_m(const BrakeParams& p, double engaged_at_s, double t);

struct EventState {
  static constexpr double kNever = std::numeric_limits<double>::quiet_NaN();
  bool started = false;                              // the first call has been made
  std::array<double, kMaxEvents> fired_at_s{};       // when each event fired (kNever: not yet)
  bool generator_connected = true;                   // the contactor, as the events leave it
  bool generator_off_below_cut_in = false;           // a normal shutdown waits for the cut-in speed
  bool connect_at_cut_in = false;                    // a start-up waits for the cut-in speed
  double brake_engaged_at_s = kNever;                // THSSBrDp of the applied brake (kNever: released)
  bool brake_by_controller = false;                  // applied through DISCON record 36 (released by it)
  // The collective manoeuvre: 0 none, 1 to feather (shutdown), 2 start-up towards the law's demand.
  int manoeuvre = 0;
  double manoeuvre_start_s = 0.0, manoeuvre_rate_rad_s = 0.0;
  std::array<double, kBladeCount> manoeuvre_from_rad{};
  double pending_shutdown_at_s = kNever;             // grid loss: the manoeuvre's start
  double pending_shutdown_rate_rad_s = 0.0;
  // Blade faults: 0 none, 1 runaway, 2 stuck.
  std::array<int, kBladeCount> fault{};
  std::array<double, kBladeCount> fault_start_s{}, fault_from_rad{}, fault_target_rad{}, fault_rate_rad_s{};
};

// The state of a run that has not started (fires nothing yet; fired_at_s all kNever).
EventState make_event_state(const EventsParams& p);

// The simulator's view of the contactor and the brake before the law runs (DISCON records 35, 36
// sent to the library): u.generator_contactor, u.shaft_brake set from s.
void event_status(const EventState& s, ControllerInput& u);

// After the law's call at time t with measurements u: fires due events, then overrides y (torque,
// pitch demands, y.generator_contactor / y.shaft_brake as the turbine sees them). The law's own
// requests come in y.generator_contactor (0: off) and y.shaft_brake (≠ 0: brake on).
void apply_events(const EventsParams& p, const ControllerInput& u, double t, double dt, EventState& s, ControllerOutput& y);

// The closed-form pitch of a ramp from `from` towards `to` at `rate`, `elapsed` after its start.
double pitch_ramp(double from, double to, double rate, double elapsed);

}  // namespace fowtsim::control
