#include "fowtsim/control/external_controller.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "fowtsim/control/swap_records.hpp"
#include "fowtsim/core/error.hpp"
#include "measurement_checks.hpp"

namespace fowtsim::control {
namespace {

using External = ExternalController;

float& record(External::State& s, int number) { return s.swap[static_cast<std::size_t>(number - 1)]; }
double read(const External::State& s, int number) { return s.swap[static_cast<std::size_t>(number - 1)]; }

// Copies a NUL-terminated string into a fixed buffer (the buffer always ends with a NUL).
void copy_string(const std::string& from, std::array<char, kStringCapacity>& to) {
  to.fill('\0');
  std::memcpy(to.data(), from.data(), std::min(from.size(), to.size() - 1));
}

std::string message_text(const External::State& s) {
  return std::string(s.message.data(), strnlen(s.message.data(), s.message.size()));
}

// Records that do not change during a run.
void fill_constant_records(const External::Params& p, External::State& s) {
  const ExternalSettings& e = p.settings;
  record(s, swap::below_rated_pitch) = static_cast<float>(e.below_rated_pitch_rad);
  record(s, swap::min_pitch) = static_cast<float>(e.min_pitch_rad);
  record(s, swap::max_pitch) = static_cast<float>(e.max_pitch_rad);
  record(s, swap::min_pitch_rate) = static_cast<float>(-e.max_pitch_rate_rad_s);
  record(s, swap::max_pitch_rate) = static_cast<float>(e.max_pitch_rate_rad_s);
  record(s, swap::pitch_actuator_type) = 0.0f;
  record(s, swap::current_pitch_rate_demand) = 0.0f;
  record(s, swap::demanded_power) = static_cast<float>(e.demanded_power_W);
  record(s, swap::pitch_control_mode) = e.individual_pitch ? 1.0f : 0.0f;
  record(s, swap::yaw_control_mode) = 0.0f;
  record(s, swap::generator_contactor) = 1.0f;  // main generator on until the controller says otherwise
  record(s, swap::shaft_brake) = 0.0f;
  record(s, swap::pitch_override) = 0.0f;   // no override requested until the controller writes one
  record(s, swap::torque_override) = 0.0f;
  record(s, swap::message_capacity) = static_cast<float>(kStringCapacity);
  record(s, swap::infile_length) = static_cast<float>(e.infile.size() + 1);
  record(s, swap::outname_length) = static_cast<float>(e.outname.size() + 1);
  record(s, swap::blade_count) = static_cast<float>(kBladeCount);
  record(s, swap::logging_capacity) = static_cast<float>(kLoggingCapacity);
  record(s, swap::logging_start) = static_cast<float>(kLoggingStart);
  record(s, swap::outname_capacity) = static_cast<float>(kStringCapacity);
  record(s, swap::swap_size) = static_cast<float>(kSwapSize);
}

// Calls the procedure with status `status` at time t. aviFAIL < 0 on the first call (status 0) is
// the controller rejecting its input (InputError: bad input, exit 2); later it is a failure
// during the run (NumericalError).
void call(const External::Params& p, int status, double t, External::State& s) {
  record(s, swap::status) = static_cast<float>(status);
  record(s, swap::time) = static_cast<float>(t);
  int fail = 0;
  s.message.fill('\0');
  p.library->procedure()(s.swap.data(), &fail, p.settings.infile.c_str(), s.outname.data(), s.message.data());
  s.message.back() = '\0';
  s.last_fail = fail;
  ++s.calls;
  s.last_call_time_s = t;
  if (fail < 0 && status == 0) {
    throw InputError({"control.dll", t, "aviFAIL", "check the controller's input file (controller.infile)"},
                     fmt::format("external controller '{}' rejected its input at its first call (aviFAIL = {}): {}",
                                 p.library->path(), fail, message_text(s)));
  }
  if (fail < 0) {
    throw NumericalError({"control.dll", t, "aviFAIL", "see the controller's message; check its parameter file"},
                         fmt::format("external controller '{}' failed at t = {} s (aviFAIL = {}): {}",
                                     p.library->path(), t, fail, message_text(s)));
  }
}

// Records 55 and 56: a controller asking the simulator's built-in pitch or torque override to take
// over (Bladed's swap array; ServoDyn's Retrieve_avrSWAP refuses any value but 0 as an error).
// fowtsim has no built-in override law either — the deck's control events (shutdown, faults,
// brake) act on the library's demands instead — so a request stops the run at its time rather
// than being silently ignored.
void check_override_requests(const External::Params& p, double t, const External::State& s) {
  for (const auto& [number, what] : {std::pair{swap::pitch_override, "pitch"}, std::pair{swap::torque_override, "torque"}}) {
    const long value = std::lround(read(s, number));
    if (value == 0) continue;
    throw NumericalError({"control.dll", t, fmt::format("avrSWAP record {}", number),
                          fmt::format("return 0 in record {}; model the manoeuvre with the deck's controller.events", number)},
                         fmt::format("external controller '{}' requests the simulator's built-in {} override (record {} = {}), "
                                     "which fowtsim does not have (nor does OpenFAST's ServoDyn)",
                                     p.library->path(), what, number, value));
  }
}

}  // namespace

External::Params External::make_params(const ExternalSettings& e) {
  std::string problems;
  const auto require = [&](bool ok, const char* key, const std::string& what) {
    if (!ok) problems += fmt::format("\n  controller.{}: {}", key, what);
  };
  require(!e.library_path.empty(), "library_path", "expected the path of the controller's shared library");
  require(!e.procedure.empty(), "procedure", "expected the name of the exported procedure (usually DISCON)");
  require(e.infile.size() < kStringCapacity, "infile", fmt::format("expected fewer than {} characters", kStringCapacity));
  require(e.outname.size() < kStringCapacity, "outname", fmt::format("expected fewer than {} characters", kStringCapacity));
  require(std::isfinite(e.min_pitch_rad) && std::isfinite(e.max_pitch_rad) && e.max_pitch_rad > e.min_pitch_rad,
          "max_pitch_rad", fmt::format("expected finite limits with max > min, found [{}, {}]", e.min_pitch_rad,
                                       e.max_pitch_rad));
  require(std::isfinite(e.max_pitch_rate_rad_s) && e.max_pitch_rate_rad_s > 0.0, "max_pitch_rate_rad_s",
          fmt::format("expected a finite value > 0, found {}", e.max_pitch_rate_rad_s));
  require(std::isfinite(e.below_rated_pitch_rad), "below_rated_pitch_rad", "expected a finite value");
  require(std::isfinite(e.demanded_power_W) && e.demanded_power_W >= 0.0, "demanded_power_W",
          fmt::format("expected a finite value ≥ 0, found {}", e.demanded_power_W));
  require(std::isfinite(e.generator_efficiency) && e.generator_efficiency > 0.0 && e.generator_efficiency <= 1.0,
          "generator_efficiency", fmt::format("expected a value in (0, 1], found {}", e.generator_efficiency));
  if (!problems.empty()) {
    throw InputError({"control.dll", std::nullopt, "controller", "fix the listed keys of the controller section"},
                     "invalid external controller settings:" + problems);
  }
  return {e, std::make_shared<const DisconLibrary>(e.library_path, e.procedure)};
}

External::State External::make_state(const Params& p) {
  State s;
  fill_constant_records(p, s);
  copy_string(p.settings.outname, s.outname);
  return s;
}

void External::advance(const Params& p, const Input& u, double t, double dt, State& s) {
  detail::check_call("control.dll", u, t, dt, s.calls > 0 ? std::optional<double>(s.last_call_time_s) : std::nullopt);
  const double eta = p.settings.generator_efficiency;
  const double shaft_power = s.torque_demand_N_m * u.generator_speed_rad_s;
  record(s, swap::communication_interval) = static_cast<float>(dt);
  record(s, swap::blade1_pitch) = static_cast<float>(u.blade_pitch_rad[0]);
  record(s, swap::blade2_pitch) = static_cast<float>(u.blade_pitch_rad[1]);
  record(s, swap::blade3_pitch) = static_cast<float>(u.blade_pitch_rad[2]);
  record(s, swap::current_pitch_demand) = static_cast<float>(s.calls > 0 ? s.pitch_demand_rad[0] : u.blade_pitch_rad[0]);
  record(s, swap::measured_shaft_power) = static_cast<float>(shaft_power);
  record(s, swap::measured_electrical_power) = static_cast<float>(shaft_power * eta);
  record(s, swap::generator_speed) = static_cast<float>(u.generator_speed_rad_s);
  record(s, swap::rotor_speed) = static_cast<float>(u.rotor_speed_rad_s);
  record(s, swap::measured_generator_torque) = static_cast<float>(s.torque_demand_N_m);
  record(s, swap::hub_wind_speed) = static_cast<float>(u.hub_wind_speed_m_s);
  // The turbine's contactor and brake as the events left them (a grid loss opens the contactor);
  // the library may change either (read back in outputs()).
  record(s, swap::generator_contactor) = static_cast<float>(u.generator_contactor);
  record(s, swap::shaft_brake) = static_cast<float>(u.shaft_brake);
  call(p, s.calls == 0 ? 0 : 1, t, s);
  check_override_requests(p, t, s);

  s.torque_demand_N_m = read(s, swap::generator_torque_demand);
  for (int b = 0; b < kBladeCount; ++b) {
    s.pitch_demand_rad[b] = read(s, p.settings.individual_pitch ? swap::blade1_pitch_demand + b : swap::collective_pitch_demand);
  }
  detail::check_demands("control.dll", t, s.torque_demand_N_m, s.pitch_demand_rad);
}

External::Output External::outputs(const Params& p, const Input& u, const State& s) {
  Output y;
  y.generator_torque_N_m = s.calls > 0 ? s.torque_demand_N_m : 0.0;
  y.blade_pitch_rad = s.calls > 0 ? s.pitch_demand_rad : u.blade_pitch_rad;
  y.generator_speed_rad_s = u.generator_speed_rad_s;
  y.generator_power_W = y.generator_torque_N_m * u.generator_speed_rad_s * p.settings.generator_efficiency;
  // Record 35: 0 = the controller opens the contactor (no torque); record 36: ≠ 0 = brake on
  // (Bladed's "shaft brake status"; ServoDyn reads 0 off, 1 brake 1 on).
  y.generator_contactor = s.calls > 0 ? static_cast<int>(std::lround(read(s, swap::generator_contactor))) : 1;
  y.shaft_brake = s.calls > 0 ? static_cast<int>(std::lround(read(s, swap::shaft_brake))) : 0;
  return y;
}

void External::finish(const Params& p, double t, State& s) {
  if (s.calls > 0) call(p, -1, t, s);
}

std::vector<ChannelInfo> External::channels(const Params&) { return controller_channels("control.dll"); }

void External::channel_values(const Params&, const Output& y, std::span<double> values) {
  controller_channel_values(y, values);
}

}  // namespace fowtsim::control
