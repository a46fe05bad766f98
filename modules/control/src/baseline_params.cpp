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

GeneratorLaw generator_law_from_name(std::string_view name) {
  if (name == "baseline") return GeneratorLaw::baseline;
  if (name == "simple_vs") return GeneratorLaw::simple_vs;
  throw InputError({"control", std::nullopt, "controller.generator", "use baseline or simple_vs"},
                   fmt::format("controller.generator: expected baseline or simple_vs, found '{}'", name));
}

PitchLaw pitch_law_from_name(std::string_view name) {
  if (name == "baseline") return PitchLaw::baseline;
  if (name == "fixed") return PitchLaw::fixed;
  throw InputError({"control", std::nullopt, "controller.pitch", "use baseline or fixed"},
                   fmt::format("controller.pitch: expected baseline or fixed, found '{}'", name));
}

double rated_speed_of_law_rad_s(const BaselineParams& p) {
  return p.generator == GeneratorLaw::simple_vs ? p.simple_vs.rated_generator_speed_rad_s : p.rated_generator_speed_rad_s;
}

namespace {

// The keys of the baseline torque schedule (38060 §7.2) and its region-2/2½ crossing.
void check_baseline_torque(const BaselineParams& p, Problems& e) {
  const auto positive = [&](const char* key, double v) { e.require(std::isfinite(v) && v > 0.0, key, v, "a finite value > 0"); };
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
  e.require(std::isfinite(p.region3_min_pitch_rad), "region3_min_pitch_rad", p.region3_min_pitch_rad, "a finite value");
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
}

// ServoDyn's simple law (simple_vs_law.cpp): a positive rated point and slip, k ≥ 0, and a quadratic
// that meets the 2½ line at or below rated speed, k VS_RtGnSp² ≤ VS_RtTq (else the torque would drop
// at VS_RtGnSp from k VS_RtGnSp² to VS_RtTq and the 2½ line would never be reached).
void check_simple_vs(const SimpleVsParams& v, Problems& e) {
  const auto positive = [&](const char* key, double x) { e.require(std::isfinite(x) && x > 0.0, key, x, "a finite value > 0"); };
  positive("simple_vs.rated_generator_speed_rad_s", v.rated_generator_speed_rad_s);
  positive("simple_vs.rated_torque_N_m", v.rated_torque_N_m);
  e.require(std::isfinite(v.region2_gain_N_m_s2) && v.region2_gain_N_m_s2 >= 0.0, "simple_vs.region2_gain_N_m_s2",
            v.region2_gain_N_m_s2, "a finite value ≥ 0");
  positive("simple_vs.slip_percent", v.slip_percent);
  e.throw_if_any();
  const double top = v.region2_gain_N_m_s2 * v.rated_generator_speed_rad_s * v.rated_generator_speed_rad_s;
  e.require(top <= v.rated_torque_N_m, "simple_vs.region2_gain_N_m_s2", v.region2_gain_N_m_s2,
            fmt::format("k with k × rated_generator_speed_rad_s² ≤ rated_torque_N_m (found k ω_rated² = {} N·m): the "
                        "region-2 curve must meet the 2½ line at or below rated speed",
                        top)
                .c_str());
}

// The gain-scheduled PI and its limits (38060 §7.3).
void check_baseline_pitch(const BaselineParams& p, Problems& e) {
  const auto positive = [&](const char* key, double v) { e.require(std::isfinite(v) && v > 0.0, key, v, "a finite value > 0"); };
  e.require(std::isfinite(p.proportional_gain_s) && p.proportional_gain_s >= 0.0, "proportional_gain_s",
            p.proportional_gain_s, "a finite value ≥ 0");
  positive("integral_gain", p.integral_gain);  // > 0: the integrator is seeded as θ/(G_K K_I)
  positive("gain_schedule_pitch_rad", p.gain_schedule_pitch_rad);
  e.require(std::isfinite(p.min_pitch_rad), "min_pitch_rad", p.min_pitch_rad, "a finite value");
  // Equal limits hold the blades at that pitch: a parked rotor feathered (DLC 6.1).
  e.require(std::isfinite(p.max_pitch_rad) && p.max_pitch_rad >= p.min_pitch_rad, "max_pitch_rad", p.max_pitch_rad,
            "a finite value ≥ min_pitch_rad");
  // G_K = 1/(1 + θ/θ_K) must stay positive and finite over the pitch range.
  e.require(p.min_pitch_rad > -p.gain_schedule_pitch_rad, "min_pitch_rad", p.min_pitch_rad,
            "a value > −gain_schedule_pitch_rad (the gain correction 1/(1+θ/θ_K) must stay positive)");
  positive("max_pitch_rate_rad_s", p.max_pitch_rate_rad_s);
}

}  // namespace

// Only the keys of the laws in use are checked: a fixed pitch needs no gains (PCMode 0 reads none).
void validate(const BaselineParams& p) {
  Problems e;
  e.require(std::isfinite(p.sample_time_s) && p.sample_time_s >= 0.0, "sample_time_s", p.sample_time_s,
            "a finite value ≥ 0 (0 = every call)");
  e.require(std::isfinite(p.filter_corner_rad_s) && p.filter_corner_rad_s > 0.0, "filter_corner_rad_s",
            p.filter_corner_rad_s, "a finite value > 0");
  e.require(std::isfinite(p.reference_speed_rad_s) && p.reference_speed_rad_s > 0.0, "reference_speed_rad_s",
            p.reference_speed_rad_s, "a finite value > 0");
  e.require(std::isfinite(p.generator_efficiency) && p.generator_efficiency > 0.0 && p.generator_efficiency <= 1.0,
            "generator_efficiency", p.generator_efficiency, "a value in (0, 1]");
  if (p.pitch == PitchLaw::baseline) check_baseline_pitch(p, e);
  e.throw_if_any();
  if (p.generator == GeneratorLaw::baseline) check_baseline_torque(p, e);
  else check_simple_vs(p.simple_vs, e);
  e.throw_if_any();
}

}  // namespace fowtsim::control
