#include "fowtsim/control/baseline_params.hpp"

#include <cmath>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::control {
namespace {

class Problems {
 public:
  void require(bool ok, const char* key, double found, const char* expected) {
    if (!ok) text_ += fmt::format("\n  controller.{}: expected {}, found {}", key, expected, found);
  }
  void throw_if_any() const {
    if (!text_.empty()) {
      throw InputError({"control", std::nullopt, "controller", "fix the listed keys of the controller section"},
                       "invalid baseline controller parameters:" + text_);
    }
  }

 private:
  std::string text_;
};

}  // namespace

Region3Torque region3_torque_from_name(std::string_view name) {
  if (name == "constant_power") return Region3Torque::constant_power;
  if (name == "constant_torque") return Region3Torque::constant_torque;
  throw InputError({"control", std::nullopt, "controller.region3_torque", "use constant_power or constant_torque"},
                   fmt::format("controller.region3_torque: expected constant_power or constant_torque, found '{}'",
                               name));
}

const char* region3_torque_name(Region3Torque mode) {
  return mode == Region3Torque::constant_power ? "constant_power" : "constant_torque";
}

void validate(const BaselineParams& p) {
  Problems e;
  const auto positive = [&](const char* key, double v) { e.require(std::isfinite(v) && v > 0.0, key, v, "a finite value > 0"); };
  const auto finite = [&](const char* key, double v) { e.require(std::isfinite(v), key, v, "a finite value"); };
  e.require(std::isfinite(p.sample_time_s) && p.sample_time_s >= 0.0, "sample_time_s", p.sample_time_s,
            "a finite value ≥ 0 (0 = every call)");
  positive("filter_corner_rad_s", p.filter_corner_rad_s);
  e.require(std::isfinite(p.cut_in_speed_rad_s) && p.cut_in_speed_rad_s >= 0.0, "cut_in_speed_rad_s",
            p.cut_in_speed_rad_s, "a finite value ≥ 0");
  e.require(std::isfinite(p.region2_start_speed_rad_s) && p.region2_start_speed_rad_s > p.cut_in_speed_rad_s,
            "region2_start_speed_rad_s", p.region2_start_speed_rad_s, "a finite value > cut_in_speed_rad_s");
  e.require(std::isfinite(p.region2_gain_N_m_s2) && p.region2_gain_N_m_s2 >= 0.0, "region2_gain_N_m_s2",
            p.region2_gain_N_m_s2, "a finite value ≥ 0");
  e.require(std::isfinite(p.rated_generator_speed_rad_s) && p.rated_generator_speed_rad_s > p.region2_start_speed_rad_s,
            "rated_generator_speed_rad_s", p.rated_generator_speed_rad_s, "a finite value > region2_start_speed_rad_s");
  positive("rated_power_W", p.rated_power_W);
  positive("slip_percent", p.slip_percent);
  positive("max_torque_N_m", p.max_torque_N_m);
  positive("max_torque_rate_N_m_s", p.max_torque_rate_N_m_s);
  finite("region3_min_pitch_rad", p.region3_min_pitch_rad);
  positive("reference_speed_rad_s", p.reference_speed_rad_s);
  e.require(std::isfinite(p.proportional_gain_s) && p.proportional_gain_s >= 0.0, "proportional_gain_s",
            p.proportional_gain_s, "a finite value ≥ 0");
  positive("integral_gain", p.integral_gain);  // > 0: the integrator is seeded as θ/(G_K K_I)
  positive("gain_schedule_pitch_rad", p.gain_schedule_pitch_rad);
  finite("min_pitch_rad", p.min_pitch_rad);
  // Equal limits hold the blades at that pitch: a parked rotor feathered (DLC 6.1).
  e.require(std::isfinite(p.max_pitch_rad) && p.max_pitch_rad >= p.min_pitch_rad, "max_pitch_rad", p.max_pitch_rad,
            "a finite value ≥ min_pitch_rad");
  // G_K = 1/(1 + θ/θ_K) must stay positive and finite over the pitch range.
  e.require(p.min_pitch_rad > -p.gain_schedule_pitch_rad, "min_pitch_rad", p.min_pitch_rad,
            "a value > −gain_schedule_pitch_rad (the gain correction 1/(1+θ/θ_K) must stay positive)");
  positive("max_pitch_rate_rad_s", p.max_pitch_rate_rad_s);
  e.require(std::isfinite(p.generator_efficiency) && p.generator_efficiency > 0.0 && p.generator_efficiency <= 1.0,
            "generator_efficiency", p.generator_efficiency, "a value in (0, 1]");
  e.throw_if_any();

  // The schedule itself: the 2½ line must meet the region-2 curve between its start and rated speed.
  const TorqueCurve c = torque_curve(p);
  e.require(c.synchronous_speed_rad_s > p.cut_in_speed_rad_s, "slip_percent", p.slip_percent,
            "a slip that puts the synchronous speed ω_rated/(1+slip/100) above cut_in_speed_rad_s");
  e.require(std::isfinite(c.transition_speed_rad_s) && c.transition_speed_rad_s >= p.region2_start_speed_rad_s &&
                c.transition_speed_rad_s <= p.rated_generator_speed_rad_s,
            "region2_gain_N_m_s2", p.region2_gain_N_m_s2,
            fmt::format("a gain whose curve k ω² meets the region-2½ line between region2_start_speed_rad_s and "
                        "rated_generator_speed_rad_s (transition speed found: {} rad/s)",
                        c.transition_speed_rad_s)
                .c_str());
  e.require(p.max_torque_N_m >= p.rated_power_W / p.rated_generator_speed_rad_s, "max_torque_N_m", p.max_torque_N_m,
            fmt::format("≥ the torque at the top of region 2½, rated_power_W / rated_generator_speed_rad_s = {} N·m",
                        p.rated_power_W / p.rated_generator_speed_rad_s)
                .c_str());
  e.throw_if_any();
}

}  // namespace fowtsim::control
