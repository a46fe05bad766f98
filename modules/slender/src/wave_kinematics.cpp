#include "fowtsim/slender/wave_kinematics.hpp"

#include <cmath>

namespace fowtsim::slender {

double wave_number(double omega, double g, double depth) {
  const double deep = omega * omega / g;
  if (depth <= 0.0) return deep;
  double k = std::max(deep, omega / std::sqrt(g * depth));  // start above the root (both bounds are)
  for (int it = 0; it < 100; ++it) {
    const double th = std::tanh(k * depth);
    const double residual = g * k * th - omega * omega;
    const double slope = g * (th + k * depth * (1.0 - th * th));
    const double step = residual / slope;
    k -= step;
    if (std::abs(step) <= 1e-15 * k) break;
  }
  return k;
}

VecXc velocity_transfer(const Model& model, double omega) {
  const Environment& env = model.environment;
  const double k = wave_number(omega, env.gravity_m_s2, env.water_depth_m);
  const auto N = model.strips.x_m.size();
  VecXc transfer = VecXc::Zero(N);
  for (Eigen::Index i = 0; i < N; ++i) {
    if (model.strips.submerged_fraction(i) <= 0.0) continue;
    const double z = std::min(model.strips.x_kinematics_m(i) - env.still_water_level_m, 0.0);
    const double h = env.water_depth_m;
    // cosh(k(h+z))/sinh(kh) written as exponentials of non-positive arguments: no overflow for kh ≫ 1.
    const double profile = h <= 0.0 ? std::exp(k * z)
                                    : (std::exp(k * z) + std::exp(-k * (2.0 * h + z))) / (1.0 - std::exp(-2.0 * k * h));
    transfer(i) = omega * profile;
  }
  return transfer;
}

MatXc velocity_transfer_table(const Model& model, const VecX& omegas) {
  MatXc table(model.strips.x_m.size(), omegas.size());
  for (Eigen::Index j = 0; j < omegas.size(); ++j) table.col(j) = velocity_transfer(model, omegas(j));
  return table;
}

}  // namespace fowtsim::slender
