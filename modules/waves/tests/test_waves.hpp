#pragma once
// Shared helpers of the waves tests: decks for the test seas and the textbook closed form of a
// regular Airy wave (Dean & Dalrymple, Water Wave Mechanics §4.4; DNV-RP-C205 Table 3-1), written
// with std::cosh / std::sinh directly — independently of the module's overflow-safe factors.
#include <cmath>
#include <limits>
#include <numbers>

#include "fowtsim/core/types.hpp"
#include "fowtsim/waves/dispersion.hpp"
#include "fowtsim/waves/wave_field.hpp"
#include "fowtsim/waves/wave_params.hpp"

namespace waves_test {

using fowtsim::Vec3;
using namespace fowtsim::waves;

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

inline WaveParams regular(double height_m, double period_s, double depth_m, double heading_deg = 0.0,
                          double phase_deg = 0.0, double dt_s = 0.1) {
  WaveParams p;
  p.model = WaveModel::regular;
  p.height_m = height_m;
  p.period_s = period_s;
  p.depth_m = depth_m;
  p.heading_deg = heading_deg;
  p.phase_deg = phase_deg;
  p.dt_s = dt_s;
  return p;
}

inline WaveParams jonswap(double hs_m, double tp_s, double gamma, double depth_m, double duration_s = 10800.0,
                          double dt_s = 0.25, std::uint64_t seed = 1) {
  WaveParams p;
  p.model = WaveModel::jonswap;
  p.hs_m = hs_m;
  p.tp_s = tp_s;
  p.gamma = gamma;
  p.depth_m = depth_m;
  p.duration_s = duration_s;
  p.dt_s = dt_s;
  p.seed = seed;
  return p;
}

// Closed-form regular wave η = a cos θ, θ = ω t − k (x cos β + y sin β) + φ, below z = 0.
struct ClosedForm {
  double eta, u_h, w, a_h, a_z, p;
};

inline ClosedForm closed_form(const WaveParams& p, const Vec3& x, double t) {
  const double a = 0.5 * p.height_m;
  const double om = 2.0 * kPi / p.period_s;
  const double k = wavenumber(om, p.depth_m, p.gravity_m_s2);
  const double beta = p.heading_deg * kPi / 180.0;
  const double theta = om * t - k * (x.x() * std::cos(beta) + x.y() * std::sin(beta)) + p.phase_deg * kPi / 180.0;
  const double h = p.depth_m, z = x.z();
  double cs, ss, cc;
  if (std::isinf(h)) {
    cs = ss = cc = std::exp(k * z);
  } else {
    cs = std::cosh(k * (z + h)) / std::sinh(k * h);
    ss = std::sinh(k * (z + h)) / std::sinh(k * h);
    cc = std::cosh(k * (z + h)) / std::cosh(k * h);
  }
  const double rho_g = p.water_density_kg_m3 * p.gravity_m_s2;
  return {a * std::cos(theta),          a * om * cs * std::cos(theta),       -a * om * ss * std::sin(theta),
          -a * om * om * cs * std::sin(theta), -a * om * om * ss * std::cos(theta), rho_g * a * cc * std::cos(theta)};
}

}  // namespace waves_test
