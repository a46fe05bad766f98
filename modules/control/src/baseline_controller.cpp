#include "fowtsim/control/baseline_controller.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "measurement_checks.hpp"

namespace fowtsim::control {

std::vector<ChannelInfo> controller_channels(const char* module) {
  return {
      {"GenTq", "kN-m", "generator torque demand (HSS), applied without generator dynamics", module},
      {"GenPwr", "kW", "electrical generator power, torque × measured generator speed × efficiency", module},
      // ServoDyn's names for the command; BldPitch· (the blades' actual pitch, ElastoDyn's) is
      // the structure's channel.
      {"BlPitchC1", "deg", "blade 1 pitch command (positive to feather)", module},
      {"BlPitchC2", "deg", "blade 2 pitch command (positive to feather)", module},
      {"BlPitchC3", "deg", "blade 3 pitch command (positive to feather)", module},
      {"GenSpeed", "rpm", "measured generator (HSS) speed", module},
  };
}

void controller_channel_values(const ControllerOutput& y, std::span<double> values) {
  if (values.size() != 6) {
    throw InputError({"control", std::nullopt, "channel values", "size values as channels(params)"},
                     fmt::format("values.size() = {} but the controller writes 6 channels", values.size()));
  }
  constexpr double kDeg = 180.0 / std::numbers::pi;
  constexpr double kRpm = 30.0 / std::numbers::pi;
  values[0] = 1e-3 * y.generator_torque_N_m;
  values[1] = 1e-3 * y.generator_power_W;
  for (int b = 0; b < kBladeCount; ++b) values[2 + b] = kDeg * y.blade_pitch_rad[b];
  values[5] = kRpm * y.generator_speed_rad_s;
}

using Controller = BaselineController;

Controller::State Controller::make_state(const Params& p) {
  validate(p);
  return {};
}

void Controller::advance(const Params& p, const Input& u, double t, double dt, State& s) {
  detail::check_call("control", u, t, dt, s.initialised ? std::optional<double>(s.last_call_time_s) : std::nullopt);
  baseline_update(p, torque_curve(p), {u.generator_speed_rad_s, u.blade_pitch_rad}, t, s);
  detail::check_demands("control", t, s.torque_demand_N_m, s.pitch_demand_rad);
}

Controller::Output Controller::outputs(const Params& p, const Input& u, const State& s) {
  State seeded;
  const State* held = &s;
  if (!s.initialised) {  // what the first call would set, without touching s
    baseline_update(p, torque_curve(p), {u.generator_speed_rad_s, u.blade_pitch_rad}, 0.0, seeded);
    held = &seeded;
  }
  Output y;
  y.generator_torque_N_m = held->torque_demand_N_m;
  y.blade_pitch_rad = held->pitch_demand_rad;
  y.generator_speed_rad_s = u.generator_speed_rad_s;
  y.generator_power_W = y.generator_torque_N_m * u.generator_speed_rad_s * p.generator_efficiency;
  return y;
}

std::vector<ChannelInfo> Controller::channels(const Params&) { return controller_channels("control"); }

void Controller::channel_values(const Params&, const Output& y, std::span<double> values) {
  controller_channel_values(y, values);
}

}  // namespace fowtsim::control
