#include "fowtsim/hydro/hydrostatics.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Geometry>
#include <numbers>

#include "fowtsim/core/error.hpp"

namespace fowtsim::hydro {
namespace {

constexpr double kPi = std::numbers::pi;

// Newton iteration on P_n from the Chebyshev-like initial guess (Numerical Recipes §4.6 "gauleg").
GaussRule make_rule(int n) {
  GaussRule r;
  r.n = n;
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
    double dp = 0.0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1.0, p1 = 0.0;
      for (int j = 1; j <= n; ++j) {
        const double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * j - 1.0) * x * p1 - (j - 1.0) * p2) / j;
      }
      dp = n * (x * p0 - p1) / (x * x - 1.0);
      const double dx = p0 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    r.nodes[i] = -x;
    r.nodes[n - 1 - i] = x;
    r.weights[i] = r.weights[n - 1 - i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
  return r;
}

// Sub-interval of [0, L] where the linear function f (f(0) = f0, f(L) = fL) is ≤ 0; lo > hi when empty.
std::pair<double, double> where_nonpositive(double f0, double fL, double L) {
  if (f0 <= 0.0 && fL <= 0.0) return {0.0, L};
  if (f0 > 0.0 && fL > 0.0) return {1.0, 0.0};
  const double root = L * f0 / (f0 - fL);  // f0 and fL of opposite signs (or one zero)
  return f0 <= 0.0 ? std::pair{0.0, root} : std::pair{root, L};
}

// Closed-form frustum between s0 and s1 (radii linear in s), fully below the plane.
void add_frustum(const MemberGeometry& m, double s0, double s1, SubmergedVolume& out) {
  const double h = s1 - s0;
  if (h <= 0.0) return;
  const double r0 = m.radius_at(s0), r1 = m.radius_at(s1);
  const double q = r0 * r0 + r0 * r1 + r1 * r1;
  const double volume = kPi * h * q / 3.0;
  const double centroid_s = s0 + h * (r0 * r0 + 2.0 * r0 * r1 + 3.0 * r1 * r1) / (4.0 * q);
  out.volume_m3 += volume;
  out.first_moment_m4 += volume * m.point_at(centroid_s);
}

// ∫ over [s1, s2] of the obliquely cut discs (hydrostatics.hpp), cosine-substituted Gauss rule.
void add_cut_region(const MemberGeometry& m, double s1, double s2, double surface_z,
                    double sin_tilt, const Vec3& w, int n, SubmergedVolume& out) {
  if (s2 <= s1) return;
  const GaussRule& rule = gauss_legendre(n);
  const double half = 0.5 * (s2 - s1);
  for (int i = 0; i < n; ++i) {
    const double phi = 0.5 * kPi * (rule.nodes[i] + 1.0);  // [−1, 1] → [0, π]
    const double s = s1 + half * (1.0 - std::cos(phi));
    const double jacobian = half * std::sin(phi) * 0.5 * kPi * rule.weights[i];  // ds = half sin φ dφ
    const double R = m.radius_at(s);
    const Vec3 c = m.point_at(s);
    const double t = std::clamp((surface_z - c.z()) / (sin_tilt * R), -1.0, 1.0);
    const double root = std::sqrt(std::max(0.0, 1.0 - t * t));
    const double area = R * R * (kPi - std::acos(t) + t * root);
    const double moment = -2.0 / 3.0 * R * R * R * root * root * root;
    out.volume_m3 += jacobian * area;
    out.first_moment_m4 += jacobian * (area * c + moment * w);
  }
}

}  // namespace

const GaussRule& gauss_legendre(int n) {
  static const std::array<GaussRule, 65> rules = [] {
    std::array<GaussRule, 65> all{};
    for (int k = 1; k <= 64; ++k) all[k] = make_rule(k);
    return all;
  }();
  if (n < 1 || n > 64) {
    throw InputError({"hydro", std::nullopt, "quadrature points", "use 1 to 64"},
                     "Gauss-Legendre rule with " + std::to_string(n) + " points is not tabulated");
  }
  return rules[n];
}

SubmergedVolume submerged_volume(const MemberGeometry& m, double surface_z, int n) {
  SubmergedVolume out;
  const double L = m.length_m;
  const Vec3 k_perp = Vec3::UnitZ() - m.axis.z() * m.axis;  // k projected on the disc plane
  const double sin_tilt = k_perp.norm();
  // Heights of a disc's highest and lowest points relative to the plane, both linear in s.
  const double top0 = m.end_a_m.z() + m.radius_a_m * sin_tilt - surface_z;
  const double topL = m.end_a_m.z() + L * m.axis.z() + m.radius_b_m * sin_tilt - surface_z;
  const double bottom0 = m.end_a_m.z() - m.radius_a_m * sin_tilt - surface_z;
  const double bottomL = m.end_a_m.z() + L * m.axis.z() - m.radius_b_m * sin_tilt - surface_z;
  const auto [wet_lo, wet_hi] = where_nonpositive(top0, topL, L);
  add_frustum(m, wet_lo, wet_hi, out);
  // Cut discs: top above the plane and bottom below it.
  const auto [a_lo, a_hi] = where_nonpositive(-top0, -topL, L);
  const auto [b_lo, b_hi] = where_nonpositive(bottom0, bottomL, L);
  const double cut_lo = std::max(a_lo, b_lo), cut_hi = std::min(a_hi, b_hi);
  // A disc thinner than 1e-12 of its radius in z (axis within 1e-12 rad of vertical) is cut over
  // a length ≤ 2R·1e-12/|e_z|: its volume is below rounding, and t would be ill-conditioned.
  if (cut_hi > cut_lo && sin_tilt > 1e-12) {
    add_cut_region(m, cut_lo, cut_hi, surface_z, sin_tilt, k_perp / sin_tilt, n, out);
  }
  return out;
}

}  // namespace fowtsim::hydro
