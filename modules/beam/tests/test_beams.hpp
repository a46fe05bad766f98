#pragma once
// Beams shared by the beam tests.
#include <cmath>

#include "fowtsim/beam/beam_model.hpp"

namespace fowtsim::beam::testing {

// A deliberately general beam: curved, twisted, fully populated symmetric positive-definite
// stiffness, mass centre off the reference line. For tangent and invariance checks.
inline BeamDefinition general_beam() {
  const ReferenceLine line = ReferenceLine::through_key_points(
      {Vec3(0, 0, 0), Vec3(0.3, 0.1, 3.0), Vec3(1.2, 0.3, 6.0), Vec3(2.5, 0.2, 8.5)},
      {0.17, 0.44, 0.70, 1.05});  // twist [rad]
  BeamDefinition def{line, {}};
  for (double eta : {0.0, 0.5, 1.0}) {
    Eigen::Matrix<double, 6, 6> a;
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) a(r, c) = std::sin(1.0 + 3.0 * r + 7.0 * c + eta);
    Station s;
    s.eta = eta;
    const Vec6 scale = (Vec6() << 2e6, 3e6, 9e6, 4e5, 6e5, 2e5).finished() * (1.5 - eta);
    s.stiffness = scale.asDiagonal() * (a * a.transpose() + 6.0 * Mat6::Identity()) / 6.0;
    s.stiffness = 0.5 * (s.stiffness + s.stiffness.transpose()).eval();
    s.stiffness = (scale.cwiseSqrt().asDiagonal() * Mat6::Identity()) * s.stiffness.eval() *
                  (scale.cwiseInverse().cwiseSqrt().asDiagonal() * Mat6::Identity());
    s.stiffness = 0.5 * (s.stiffness + s.stiffness.transpose()).eval();
    const double m = 50.0 * (1.2 - eta);
    const Vec3 e(0.05, -0.02, 0.0);
    Mat3 et;
    et << 0, -e.z(), e.y(), e.z(), 0, -e.x(), -e.y(), e.x(), 0;
    s.mass.setZero();
    s.mass.topLeftCorner<3, 3>() = m * Mat3::Identity();
    s.mass.block<3, 3>(3, 0) = m * et;
    s.mass.block<3, 3>(0, 3) = (m * et).transpose();
    s.mass.bottomRightCorner<3, 3>() << 3.0, 0.1, 0.0, 0.1, 1.0, 0.0, 0.0, 0.0, 4.0;
    def.stations.push_back(s);
  }
  def.stiffness_damping = Vec6::Constant(0.01);
  return def;
}

}  // namespace fowtsim::beam::testing
