#include "fowtsim/core/rotation.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "fowtsim/core/error.hpp"

namespace fowtsim {


Vec3 axial(const Mat3& m) {
  return 0.5 * Vec3(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1));
}

Mat3 euler123_to_matrix(const Vec3& theta) {
  const double c1 = std::cos(theta[0]), s1 = std::sin(theta[0]);
  const double c2 = std::cos(theta[1]), s2 = std::sin(theta[1]);
  const double c3 = std::cos(theta[2]), s3 = std::sin(theta[2]);
  Mat3 t;  // seed 000 eq. 3.1, entry by entry
  t << c2 * c3, -c2 * s3, s2,                                   //
      c1 * s3 + c3 * s1 * s2, c1 * c3 - s1 * s2 * s3, -c2 * s1,  //
      s1 * s3 - c1 * c3 * s2, c3 * s1 + c1 * s2 * s3, c1 * c2;
  return t;
}

Vec3 matrix_to_euler123(const Mat3& t) {
  const double s2 = std::clamp(t(0, 2), -1.0, 1.0);
  const double theta2 = std::asin(s2);
  const double c2 = std::sqrt(std::max(0.0, 1.0 - s2 * s2));
  if (c2 < 1e-12) {
    // Gimbal lock: θ1 and θ3 rotate about the same axis; put it all in θ1 (θ3 = 0), read from
    // t22 = cos θ1, t32 = sin θ1 of eq. 3.1 with θ3 = 0.
    return {std::atan2(t(2, 1), t(1, 1)), theta2, 0.0};
  }
  return {std::atan2(-t(1, 2), t(2, 2)), theta2, std::atan2(-t(0, 1), t(0, 0))};
}

Mat3 small_angle_matrix(const Vec3& theta) { return Mat3::Identity() + skew(theta); }

Mat3 euler123_rate_matrix(const Vec3& theta) {
  // ω = R_z(θ3)^T R_y(θ2)^T e1 θ̇1 + R_z(θ3)^T e2 θ̇2 + e3 θ̇3 for T = R_x R_y R_z.
  const double c2 = std::cos(theta[1]), s2 = std::sin(theta[1]);
  const double c3 = std::cos(theta[2]), s3 = std::sin(theta[2]);
  Mat3 e;
  e << c2 * c3, s3, 0.0,  //
      -c2 * s3, c3, 0.0,  //
      s2, 0.0, 1.0;
  return e;
}

Vec3 euler123_rates_from_body_angular_velocity(const Vec3& theta, const Vec3& omega) {
  const double c2 = std::cos(theta[1]);
  if (std::abs(c2) < 1e-9) {
    throw NumericalError({"core.rotation", {}, "theta2", "use a rotation matrix or quaternion near ±90°"},
                         "Euler 1-2-3 rates are singular at theta2 = ±90°");
  }
  return euler123_rate_matrix(theta).inverse() * omega;
}

Vec3 body_angular_velocity(const Mat3& t, const Mat3& t_dot) { return axial(t.transpose() * t_dot); }

Vec3 body_angular_acceleration(const Mat3& t, const Mat3& t_dot, const Mat3& t_ddot) {
  return axial(t_dot.transpose() * t_dot + t.transpose() * t_ddot);
}

Vec3 spatial_angular_velocity(const Mat3& t, const Mat3& t_dot) { return axial(t_dot * t.transpose()); }

Mat3 matrix_rate(const Mat3& t, const Vec3& omega) { return t * skew(omega); }

Mat3 matrix_second_rate(const Mat3& t, const Vec3& omega, const Vec3& omega_dot) {
  const Mat3 w = skew(omega);
  return t * (w * w + skew(omega_dot));
}

}  // namespace fowtsim
