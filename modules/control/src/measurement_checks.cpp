#include "measurement_checks.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::control::detail {
namespace {

[[noreturn]] void fail(const char* module, double t, const std::string& variable, const std::string& hint,
                       const std::string& message) {
  throw NumericalError({module, t, variable, hint}, fmt::format("{} at t = {} s: {}", module, t, message));
}

}  // namespace

void check_call(const char* module, const ControllerInput& u, double t, double dt,
                std::optional<double> last_call_time_s) {
  const char* hint = "check the turbine state handed to the controller (reduce the time step if it diverged)";
  if (!std::isfinite(t)) fail(module, t, "t", "pass a finite simulation time", "time is not finite");
  if (!(std::isfinite(dt) && dt > 0.0)) {
    fail(module, t, "dt", "pass the caller's step, > 0", fmt::format("step dt = {} is not finite and > 0", dt));
  }
  if (!std::isfinite(u.generator_speed_rad_s)) {
    fail(module, t, "generator speed", hint, fmt::format("generator speed = {} rad/s", u.generator_speed_rad_s));
  }
  if (!std::isfinite(u.rotor_speed_rad_s)) {
    fail(module, t, "rotor speed", hint, fmt::format("rotor speed = {} rad/s", u.rotor_speed_rad_s));
  }
  if (!std::isfinite(u.hub_wind_speed_m_s)) {
    fail(module, t, "hub wind speed", hint, fmt::format("hub wind speed = {} m/s", u.hub_wind_speed_m_s));
  }
  for (int b = 0; b < kBladeCount; ++b) {
    if (!std::isfinite(u.blade_pitch_rad[b])) {
      fail(module, t, fmt::format("blade {} pitch", b + 1), hint,
           fmt::format("measured blade {} pitch = {} rad", b + 1, u.blade_pitch_rad[b]));
    }
  }
  if (last_call_time_s && t < *last_call_time_s) {
    fail(module, t, "t", "restore the controller State together with the time it belongs to",
         fmt::format("called at t = {} s, earlier than its previous call at {} s", t, *last_call_time_s));
  }
}

void check_demands(const char* module, double t, double torque_N_m, const std::array<double, kBladeCount>& pitch_rad) {
  const char* hint = "check the controller parameters and the measurements (reduce the time step if they diverged)";
  if (!std::isfinite(torque_N_m)) {
    fail(module, t, "generator torque demand", hint, fmt::format("generator torque demand = {} N·m", torque_N_m));
  }
  for (int b = 0; b < kBladeCount; ++b) {
    if (!std::isfinite(pitch_rad[b])) {
      fail(module, t, fmt::format("blade {} pitch demand", b + 1), hint,
           fmt::format("blade {} pitch demand = {} rad", b + 1, pitch_rad[b]));
    }
  }
}

}  // namespace fowtsim::control::detail
