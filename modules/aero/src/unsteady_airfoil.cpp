#include "fowtsim/aero/unsteady_airfoil.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fowtsim::aero {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;
constexpr double kGrid = 0.05 * kDegree;        // scan step of the polar [rad]
constexpr double kBlend = 5.0 * kDegree;         // cosine blend to the static polar below the cutout
// T_u = c/(2W) kept in [1e-3, 50] s (AeroDyn theory manual, UA notations): W → 0 would stop the
// states (T_u → ∞) and make the added-mass term π T_u ω unbounded.
constexpr double kMinTimeUnit = 1e-3, kMaxTimeUnit = 50.0;

double time_unit(const SectionMotion& m) {
  const double w = std::max(m.speed_m_s, 0.5 * m.chord_m / kMaxTimeUnit);
  return std::clamp(0.5 * m.chord_m / w, kMinTimeUnit, kMaxTimeUnit);
}

// ¾-chord angle: rotation ω about z_a moves the ¾-chord point (c/2 behind the ¼ chord) against
// x_a, which adds ω c/2 to the normal relative velocity.
double alpha34(const SectionMotion& m) {
  return std::atan2(m.speed_m_s * std::sin(m.alpha_rad) + 0.5 * m.pitch_rate_rad_s * m.chord_m,
                    m.speed_m_s * std::cos(m.alpha_rad));
}

// Weight of the dynamic coefficients: 1 up to 5° below the cutout, 0 beyond it.
double dynamic_weight(const UnsteadyAirfoilConstants& k, double alpha_rad) {
  const double a = std::abs(wrap_angle(alpha_rad));
  if (a <= k.cutout_rad - kBlend) return 1.0;
  if (a >= k.cutout_rad) return 0.0;
  return 0.5 * (1.0 + std::cos(kPi * (a - (k.cutout_rad - kBlend)) / kBlend));
}

double attached_lift(const SeparationData& s, double alpha_e) { return s.lift_slope_per_rad * (alpha_e - s.alpha0_rad); }

double separation_at(const Polar& polar, const SeparationData& s, double alpha) {
  return static_separation(s, alpha, polar.evaluate(alpha).cl).f;
}

}  // namespace

double first_order_hold(double x0, double lambda, double gain, double u0, double u1, double h) {
  const double lh = lambda * h;
  const double decay = std::exp(-lh);
  // (1 − e^{−λh})/(λh), its series below 1e-8 (relative error < 1e-16 there).
  const double mean = lh < 1e-8 ? 1.0 - 0.5 * lh : -std::expm1(-lh) / lh;
  return decay * x0 + gain * (u1 - decay * u0 - mean * (u1 - u0));
}

SeparationData derive_separation(const Polar& polar) {
  SeparationData s;
  auto cl = [&](double a) { return polar.evaluate(a).cl; };
  // α0: the rising zero crossing of C_l^st nearest 0 within ±20°.
  double best = 1e9;
  for (double a = -20.0 * kDegree; a < 20.0 * kDegree; a += kGrid) {
    const double c0 = cl(a), c1 = cl(a + kGrid);
    if (c0 <= 0.0 && c1 > 0.0) {
      double lo = a, hi = a + kGrid;
      for (int i = 0; i < 60 && hi - lo > 1e-12; ++i) {
        const double mid = 0.5 * (lo + hi);
        (cl(mid) <= 0.0 ? lo : hi) = mid;
      }
      const double root = 0.5 * (lo + hi);
      if (std::abs(root) < std::abs(best)) best = root;
    }
  }
  if (best > 1e8) return s;  // no attached lift range: the model passes the static polar through
  s.alpha0_rad = best;
  s.cd0 = polar.evaluate(best).cd;
  // C_l,α: least-squares slope of C_l^st over α0 − 3° … α0 + 5° (the linear part of the NREL 5MW
  // tables; the range is asymmetric because positive stall is nearer α0 than negative stall on a
  // cambered airfoil).
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  int count = 0;
  for (int i = -60; i <= 100; ++i) {
    const double d = i * kGrid, c = cl(best + d);
    sx += d, sy += c, sxx += d * d, sxy += d * c;
    ++count;
  }
  const double slope = (count * sxy - sx * sy) / (count * sxx - sx * sx);
  if (!(slope > 0.0)) return s;
  s.lift_slope_per_rad = slope;
  // First zero of f_st (ratio C_l^st/(C_l,α(α−α0)) down to ¼) on each side, within ±90° of α0,
  // searched from 2° off α0: closer in the ratio is one small number over another (DU40's table
  // has a plateau, C_l ≈ 0.003…0.014 from −3° to −1.5°, that would end the attached range at α0).
  auto first_zero = [&](double direction) {
    for (int i = 40; i * kGrid <= 90.0 * kDegree; ++i) {
      const double d = direction * i * kGrid;
      if (cl(best + d) / (slope * d) <= 0.25) return best + d;
    }
    return best + direction * 90.0 * kDegree;
  };
  s.alpha_high_rad = first_zero(1.0);
  s.alpha_low_rad = first_zero(-1.0);
  s.lifting = true;
  return s;
}

StaticSeparation static_separation(const SeparationData& s, double alpha_rad, double cl_static) {
  StaticSeparation out;
  if (!s.lifting || alpha_rad <= s.alpha_low_rad || alpha_rad >= s.alpha_high_rad) {
    out.f = 0.0;
    out.cl_fs = cl_static;
    return out;
  }
  const double linear = attached_lift(s, alpha_rad);
  if (std::abs(alpha_rad - s.alpha0_rad) < 1e-9) {  // at α0: f = 1, C_l,fs = C_l^st/2 (both → 0)
    out.f = 1.0;
    out.cl_fs = 0.5 * cl_static;
    return out;
  }
  const double ratio = cl_static / linear;
  if (ratio <= 0.25) {
    out.f = 0.0;
    out.cl_fs = cl_static;
    return out;
  }
  // √f_st; above 1 where the polar is locally steeper than C_l,α (not clipped: the Kirchhoff
  // relation then still returns C_l^st exactly in the steady state).
  const double root_f = 2.0 * std::sqrt(ratio) - 1.0;
  out.f = root_f * root_f;
  out.cl_fs = linear * (1.0 + 3.0 * root_f) / (4.0 * (1.0 + root_f));
  return out;
}

UnsteadyAirfoilState unsteady_airfoil_steady(const Polar& polar, const SeparationData& sep,
                                             const UnsteadyAirfoilConstants& k, const SectionMotion& m) {
  UnsteadyAirfoilState st;
  SectionMotion held = m;
  held.alpha_rad = std::clamp(wrap_angle(m.alpha_rad), -k.cutout_rad, k.cutout_rad);
  st.time_unit_s = time_unit(held);
  st.pitch_rate_rad_s = held.pitch_rate_rad_s;
  st.alpha34_rad = alpha34(held);
  st.x1 = kJonesA1 * st.alpha34_rad;
  st.x2 = kJonesA2 * st.alpha34_rad;
  if (!sep.lifting) return st;
  // α_E = α34 exactly in the steady state only up to round-off of (1 − A1 − A2) + A1 + A2; the
  // states are set from the same expression the outputs use, so the steady outputs are exact.
  const double alpha_e = st.alpha34_rad * (1.0 - kJonesA1 - kJonesA2) + st.x1 + st.x2;
  st.x3 = attached_lift(sep, alpha_e) + kPi * st.time_unit_s * st.pitch_rate_rad_s;
  st.x4 = separation_at(polar, sep, st.x3 / sep.lift_slope_per_rad + sep.alpha0_rad);
  return st;
}

void advance_unsteady_airfoil(const Polar& polar, const SeparationData& sep, const UnsteadyAirfoilConstants& k,
                              const SectionMotion& end, double dt, UnsteadyAirfoilState& st) {
  if (!sep.lifting || std::abs(wrap_angle(end.alpha_rad)) >= k.cutout_rad || !(dt > 0.0)) {
    st = unsteady_airfoil_steady(polar, sep, k, end);
    return;
  }
  const double tu1 = time_unit(end), a1 = alpha34(end), w1 = end.pitch_rate_rad_s;
  const double tu = 0.5 * (st.time_unit_s + tu1);  // T_u frozen over the step at its mean
  // Inputs of x3 and x4 at the start, from the states there.
  const double alpha_e0 = st.alpha34_rad * (1.0 - kJonesA1 - kJonesA2) + st.x1 + st.x2;
  const double clp0 = attached_lift(sep, alpha_e0) + kPi * st.time_unit_s * st.pitch_rate_rad_s;
  const double f0 = separation_at(polar, sep, st.x3 / sep.lift_slope_per_rad + sep.alpha0_rad);
  st.x1 = first_order_hold(st.x1, kJonesB1 / tu, kJonesA1, st.alpha34_rad, a1, dt);
  st.x2 = first_order_hold(st.x2, kJonesB2 / tu, kJonesA2, st.alpha34_rad, a1, dt);
  const double alpha_e1 = a1 * (1.0 - kJonesA1 - kJonesA2) + st.x1 + st.x2;
  const double clp1 = attached_lift(sep, alpha_e1) + kPi * tu1 * w1;
  const double x3_0 = st.x3;
  st.x3 = first_order_hold(x3_0, 1.0 / (k.pressure_time_constant * tu), 1.0, clp0, clp1, dt);
  const double f1 = separation_at(polar, sep, st.x3 / sep.lift_slope_per_rad + sep.alpha0_rad);
  st.x4 = std::max(first_order_hold(st.x4, 1.0 / (k.separation_time_constant * tu), 1.0, f0, f1, dt), 0.0);
  st.alpha34_rad = a1;
  st.time_unit_s = tu1;
  st.pitch_rate_rad_s = w1;
}

AirfoilCoefficients unsteady_coefficients(const Polar& polar, const SeparationData& sep,
                                          const UnsteadyAirfoilConstants& k, const SectionMotion& now,
                                          const UnsteadyAirfoilState& st) {
  const AirfoilCoefficients fixed = polar.evaluate(now.alpha_rad);
  const double weight = sep.lifting ? dynamic_weight(k, now.alpha_rad) : 0.0;
  if (weight == 0.0) return fixed;
  const double tu = time_unit(now), omega = now.pitch_rate_rad_s;
  const double alpha_e = alpha34(now) * (1.0 - kJonesA1 - kJonesA2) + st.x1 + st.x2;
  const AirfoilCoefficients at_e = polar.evaluate(alpha_e);
  const StaticSeparation fs = static_separation(sep, alpha_e, at_e.cl);
  const double f = st.x4;
  AirfoilCoefficients dynamic;
  dynamic.cl = f * attached_lift(sep, alpha_e) + (1.0 - f) * fs.cl_fs + kPi * tu * omega;
  const double extra_separation = 0.5 * (std::sqrt(fs.f) - std::sqrt(f)) - 0.25 * (fs.f - f);
  dynamic.cd = at_e.cd + (now.alpha_rad - alpha_e) * dynamic.cl + (at_e.cd - sep.cd0) * extra_separation;
  dynamic.cm = at_e.cm - 0.5 * kPi * tu * omega;
  if (weight == 1.0) return dynamic;
  return {weight * dynamic.cl + (1.0 - weight) * fixed.cl, weight * dynamic.cd + (1.0 - weight) * fixed.cd,
          weight * dynamic.cm + (1.0 - weight) * fixed.cm};
}

}  // namespace fowtsim::aero
