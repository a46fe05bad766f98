#include "fowtsim/control/baseline_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fowtsim::control {
namespace {

// Floating-point slack on "a sample time has elapsed": times are sums of steps, so a due update
// may appear a few ulps early. Relative to the time itself [s/s].
constexpr double kTimeRoundoff = 1e-12;

// Region and torque of the generator law in use, before any rate limit: the baseline schedule on
// the filtered speed and blade 1's last pitch demand, or ServoDyn's simple law on the measured
// speed (VSContrl 1 acts on the generator speed itself).
void set_torque_target(const BaselineParams& p, const TorqueCurve& c, const Measurements& m, BaselineState& s) {
  if (p.generator == GeneratorLaw::simple_vs) {
    const SimpleVsCurve sc = simple_vs_curve(p.simple_vs);
    s.region = simple_vs_region(p.simple_vs, sc, m.generator_speed_rad_s);
    s.torque_demand_N_m = simple_vs_torque(p.simple_vs, sc, s.region, m.generator_speed_rad_s);
  } else {
    s.region = torque_region(p, c, s.filtered_speed_rad_s, s.pitch_demand_rad[0]);
    s.torque_demand_N_m = scheduled_torque(p, c, s.region, s.filtered_speed_rad_s);
  }
}

}  // namespace

TorqueCurve torque_curve(const BaselineParams& p) {
  TorqueCurve c;
  const double k = p.region2_gain_N_m_s2;
  const double w_rated = p.rated_generator_speed_rad_s;
  c.synchronous_speed_rad_s = w_rated / (1.0 + 0.01 * p.slip_percent);
  // 2½: straight line of an induction machine with the given slip, through rated power at ω_rated,gen.
  c.slope_region25_N_m_s = (p.rated_power_W / w_rated) / (w_rated - c.synchronous_speed_rad_s);
  // 1½: straight line from zero torque at cut-in to the region-2 curve at its start.
  const double w2 = p.region2_start_speed_rad_s;
  c.slope_region15_N_m_s = k * w2 * w2 / (w2 - p.cut_in_speed_rad_s);
  // 2 → 2½ where k ω² = S (ω − ω_s): k ω² − S ω + S ω_s = 0, lower root (the upper one lies beyond
  // the line's intended range). With k = 0 region 2 has no torque and the line starts at ω_s.
  const double s = c.slope_region25_N_m_s;
  if (k == 0.0) {
    c.transition_speed_rad_s = c.synchronous_speed_rad_s;
  } else {
    const double discriminant = s * s - 4.0 * k * s * c.synchronous_speed_rad_s;
    c.transition_speed_rad_s = discriminant >= 0.0 ? (s - std::sqrt(discriminant)) / (2.0 * k)
                                                   : std::numeric_limits<double>::quiet_NaN();
  }
  c.rated_torque_N_m = p.rated_power_W / p.reference_speed_rad_s;
  return c;
}

double gain_correction(const BaselineParams& p, double pitch_rad) {
  return 1.0 / (1.0 + pitch_rad / p.gain_schedule_pitch_rad);
}

TorqueRegion torque_region(const BaselineParams& p, const TorqueCurve& c, double w, double pitch_rad) {
  if (w >= p.rated_generator_speed_rad_s || pitch_rad >= p.region3_min_pitch_rad) return TorqueRegion::region3;
  if (w <= p.cut_in_speed_rad_s) return TorqueRegion::region1;
  if (w < p.region2_start_speed_rad_s) return TorqueRegion::region15;
  if (w < c.transition_speed_rad_s) return TorqueRegion::region2;
  return TorqueRegion::region25;
}

double scheduled_torque(const BaselineParams& p, const TorqueCurve& c, TorqueRegion region, double w) {
  double torque = 0.0;
  switch (region) {
    case TorqueRegion::region1: torque = 0.0; break;
    case TorqueRegion::region15: torque = c.slope_region15_N_m_s * (w - p.cut_in_speed_rad_s); break;
    case TorqueRegion::region2: torque = p.region2_gain_N_m_s2 * w * w; break;
    case TorqueRegion::region25: torque = c.slope_region25_N_m_s * (w - c.synchronous_speed_rad_s); break;
    case TorqueRegion::region3:
      torque = p.region3_torque == Region3Torque::constant_power ? p.rated_power_W / w : c.rated_torque_N_m;
      break;
  }
  return std::min(torque, p.max_torque_N_m);
}

void baseline_update(const BaselineParams& p, const TorqueCurve& c, const Measurements& m, double time_s,
                     BaselineState& s) {
  if (!s.initialised) {
    s.filtered_speed_rad_s = m.generator_speed_rad_s;
    s.pitch_demand_rad = m.blade_pitch_rad;  // with a fixed pitch, held there for good (PCMode 0)
    // Integral term G_K K_I ∫e = θ_measured: the pitch loop starts where the blades are.
    if (p.pitch == PitchLaw::baseline) {
      const double gk = gain_correction(p, m.blade_pitch_rad[0]);
      s.speed_error_integral_rad = m.blade_pitch_rad[0] / (gk * p.integral_gain);
    }
    set_torque_target(p, c, m, s);
    s.last_call_time_s = time_s;
    s.last_update_time_s = time_s;
    s.initialised = true;
    return;
  }
  const double since_call = time_s - s.last_call_time_s;
  if (!(since_call > 0.0)) return;

  // Single-pole low-pass, exact for a speed held over the interval (38060 §7.1):
  // ω_f ← (1 − α) ω + α ω_f, α = exp(−ω_c Δt).
  const double alpha = std::exp(-p.filter_corner_rad_s * since_call);
  s.filtered_speed_rad_s = (1.0 - alpha) * m.generator_speed_rad_s + alpha * s.filtered_speed_rad_s;
  s.last_call_time_s = time_s;

  const double elapsed = time_s - s.last_update_time_s;
  if (elapsed < p.sample_time_s - kTimeRoundoff * std::max(1.0, std::abs(time_s))) return;
  const double w = s.filtered_speed_rad_s;
  const double last_pitch = s.pitch_demand_rad[0];  // blade 1's last demand stands for the collective pitch

  // Torque: schedule, then the rate limit over the elapsed time (38060 §7.2); the simple law has no
  // rate limit.
  const double held_torque = s.torque_demand_N_m;
  set_torque_target(p, c, m, s);
  if (p.generator == GeneratorLaw::baseline) {
    const double max_change = p.max_torque_rate_N_m_s * elapsed;
    s.torque_demand_N_m = held_torque + std::clamp(s.torque_demand_N_m - held_torque, -max_change, max_change);
  }
  s.last_update_time_s = time_s;
  if (p.pitch == PitchLaw::fixed) return;  // PCMode 0: the first call's pitch stays

  // Pitch: gain-scheduled PI on the filtered speed error (38060 §7.3). Anti-windup: the integral
  // term G_K K_I ∫e is kept within [θ_min, θ_max], so it never winds beyond the actuator range.
  const double gk = gain_correction(p, last_pitch);
  const double error = w - p.reference_speed_rad_s;
  const double ki = gk * p.integral_gain;
  s.speed_error_integral_rad = std::clamp(s.speed_error_integral_rad + error * elapsed,
                                          p.min_pitch_rad / ki, p.max_pitch_rad / ki);
  const double command = std::clamp(gk * p.proportional_gain_s * error + ki * s.speed_error_integral_rad,
                                    p.min_pitch_rad, p.max_pitch_rad);
  // Rate limit relative to each blade's measured pitch, then the angle limits again.
  const double max_step = p.max_pitch_rate_rad_s * elapsed;
  for (int b = 0; b < kBladeCount; ++b) {
    const double measured = m.blade_pitch_rad[b];
    s.pitch_demand_rad[b] =
        std::clamp(measured + std::clamp(command - measured, -max_step, max_step), p.min_pitch_rad, p.max_pitch_rad);
  }
}

}  // namespace fowtsim::control
