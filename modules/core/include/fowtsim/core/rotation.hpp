#pragma once
// Rotation algebra of seed 000 (Ch. 2): transformation matrices, skew/axial, Euler 1-2-3 angles,
// small-angle forms and angular velocity/acceleration from a transformation matrix.
//
// Notation (seed 000 §2.2.2): T_ab rotates components from frame b to frame a, v_a = T_ab v_b;
// T_ba = T_ab^T. Angular velocities returned by body_* are resolved in the moving frame (the
// frame the matrix rotates *from*), as Ω_f in eq. 2.2.
#include <cmath>

#include "fowtsim/core/types.hpp"

namespace fowtsim {

// Skew-symmetric matrix ã with ã b = a × b. Inline: it sits in the beam's innermost loops.
inline Mat3 skew(const Vec3& a) {
  Mat3 m;
  m << 0.0, -a.z(), a.y(),  //
      a.z(), 0.0, -a.x(),   //
      -a.y(), a.x(), 0.0;
  return m;
}

// ã b̃ = b aᵀ − (a·b) I: a product of two skew matrices without the 3×3 product.
inline Mat3 skew_product(const Vec3& a, const Vec3& b) {
  return b * a.transpose() - a.dot(b) * Mat3::Identity();
}

// Elementary rotations T_ab by angle a about axis x, y or z of frame b (right-hand rule), from
// one std::cos and one std::sin with exact 0 and 1 entries. Inline: the rotor places every blade
// node through them at every step.
inline Mat3 rotation_x(double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  Mat3 r;
  r << 1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c;
  return r;
}
inline Mat3 rotation_y(double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  Mat3 r;
  r << c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c;
  return r;
}
inline Mat3 rotation_z(double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  Mat3 r;
  r << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  return r;
}

// Axial vector of the skew-symmetric part of m: axial(skew(a)) = a for every a.
Vec3 axial(const Mat3& m);

// T_ld = R_x(θ1) R_y(θ2) R_z(θ3), 1-2-3 sequenced Euler angles (seed 000 eq. 3.1).
Mat3 euler123_to_matrix(const Vec3& theta_rad);

// Inverse of euler123_to_matrix with θ2 in [-π/2, π/2]. At gimbal lock (|cos θ2| < 1e-12) θ3 is
// set to 0 and θ1 takes the whole rotation about the common axis.
Vec3 matrix_to_euler123(const Mat3& t);

// Small-angle form T ≈ I + θ̃ (seed 000 eq. 2.22); its transpose is I − θ̃ (eq. 2.23).
Mat3 small_angle_matrix(const Vec3& theta_rad);

// E(θ) with ω = E(θ) θ̇: body-frame angular velocity of the 1-2-3 Euler angles.
Mat3 euler123_rate_matrix(const Vec3& theta_rad);

// θ̇ from the body-frame angular velocity; throws NumericalError near gimbal lock (|cos θ2| < 1e-9).
Vec3 euler123_rates_from_body_angular_velocity(const Vec3& theta_rad, const Vec3& omega_rad_s);

// ω with ω̃ = T^T Ṫ: angular velocity in the moving frame (seed 000 eqs. 2.1, 2.2).
Vec3 body_angular_velocity(const Mat3& t, const Mat3& t_dot);

// ω̇ with ω̇̃ = Ṫ^T Ṫ + T^T T̈ (seed 000 eqs. 2.3, 2.4), in the moving frame.
Vec3 body_angular_acceleration(const Mat3& t, const Mat3& t_dot, const Mat3& t_ddot);

// Angular velocity in the fixed frame: ω̃_fixed = Ṫ T^T (= T ω̃_body T^T).
Vec3 spatial_angular_velocity(const Mat3& t, const Mat3& t_dot);

// Ṫ = T ω̃ and T̈ = T (ω̃ ω̃ + ω̇̃) for body-frame ω, ω̇: the inverse maps of the above.
Mat3 matrix_rate(const Mat3& t, const Vec3& omega_body_rad_s);
Mat3 matrix_second_rate(const Mat3& t, const Vec3& omega_body_rad_s,
                        const Vec3& omega_dot_body_rad_s2);

}  // namespace fowtsim
