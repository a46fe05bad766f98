// Rotation algebra of seed 000 Ch. 2: round trips, orthogonality, small-angle forms and the
// angular velocity/acceleration formulas (eqs. 2.1–2.4) checked by finite differences.
#include <cmath>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include "fowtsim/core/rotation.hpp"

using namespace fowtsim;

namespace {

// Smooth test trajectory of Euler angles spanning large angles (no gimbal lock: |θ2| < 1.2 rad).
Vec3 theta_of(double t) { return {1.1 * std::sin(0.7 * t), 1.2 * std::sin(0.4 * t + 0.3), 2.0 * std::cos(0.9 * t)}; }
Vec3 theta_rate_of(double t) {
  return {0.77 * std::cos(0.7 * t), 0.48 * std::cos(0.4 * t + 0.3), -1.8 * std::sin(0.9 * t)};
}

}  // namespace

TEST_CASE("skew and axial are inverse and skew represents the cross product", "[unit][rotation]") {
  const Vec3 a(0.3, -1.2, 2.5), b(-0.7, 0.4, 1.1);
  CHECK((skew(a) * b - a.cross(b)).norm() < 1e-15);       // exact up to rounding
  CHECK((axial(skew(a)) - a).norm() == 0.0);              // pure copies of entries
  CHECK((skew(a) + skew(a).transpose()).norm() == 0.0);   // skew-symmetric by construction
}

TEST_CASE("Euler 1-2-3 matrix matches the seed's entries and is orthogonal", "[unit][rotation]") {
  // Intent: eq. 3.1 is R_x(θ1) R_y(θ2) R_z(θ3); check against the product of elementary rotations.
  const Vec3 th(0.4, -0.9, 2.2);
  const Mat3 rx = Eigen::AngleAxisd(th[0], Vec3::UnitX()).toRotationMatrix();
  const Mat3 ry = Eigen::AngleAxisd(th[1], Vec3::UnitY()).toRotationMatrix();
  const Mat3 rz = Eigen::AngleAxisd(th[2], Vec3::UnitZ()).toRotationMatrix();
  const Mat3 t = euler123_to_matrix(th);
  CHECK((t - rx * ry * rz).norm() < 1e-15);                       // rounding only
  CHECK((t.transpose() * t - Mat3::Identity()).norm() < 1e-15);   // orthogonal, eq. below 2.1
  CHECK(std::abs(t.determinant() - 1.0) < 1e-15);                 // proper rotation
}

TEST_CASE("Euler 1-2-3 round trip over a grid of large angles", "[unit][rotation]") {
  double worst = 0.0;
  for (double a = -3.0; a <= 3.0; a += 0.5)
    for (double b = -1.5; b <= 1.5; b += 0.25)
      for (double c = -3.0; c <= 3.0; c += 0.5) {
        const Vec3 th(a, b, c);
        worst = std::max(worst, (matrix_to_euler123(euler123_to_matrix(th)) - th).norm());
      }
  CHECK(worst < 1e-12);  // measured 4e-15 away from lock; 1e-12 leaves room near |θ2| = 1.5
}

TEST_CASE("Euler 1-2-3 at gimbal lock returns an equivalent rotation", "[unit][rotation]") {
  const Vec3 th(0.3, M_PI / 2, 0.5);
  const Mat3 t = euler123_to_matrix(th);
  CHECK((euler123_to_matrix(matrix_to_euler123(t)) - t).norm() < 1e-12);  // same matrix
}

TEST_CASE("small-angle matrix is first-order accurate", "[unit][rotation]") {
  // eq. 2.22: T ≈ I + θ̃ with an O(|θ|²) remainder — halving θ quarters the error.
  const Vec3 dir(0.3, -0.5, 0.8);
  const double e1 = (euler123_to_matrix(1e-2 * dir) - small_angle_matrix(1e-2 * dir)).norm();
  const double e2 = (euler123_to_matrix(5e-3 * dir) - small_angle_matrix(5e-3 * dir)).norm();
  CHECK(e1 / e2 == Approx(4.0).epsilon(0.01));  // second-order remainder, ratio 4 within 1 %
  CHECK((small_angle_matrix(dir).transpose() - (Mat3::Identity() - skew(dir))).norm() == 0.0);  // eq. 2.23
}

TEST_CASE("angular velocity from T and Tdot (eq. 2.2) matches the Euler-rate map, by finite differences",
          "[unit][rotation]") {
  const double h = 1e-5;
  for (double t : {0.0, 0.8, 2.3, 5.1}) {
    const Mat3 tdot = (euler123_to_matrix(theta_of(t + h)) - euler123_to_matrix(theta_of(t - h))) / (2 * h);
    const Vec3 omega_fd = body_angular_velocity(euler123_to_matrix(theta_of(t)), tdot);
    const Vec3 omega = euler123_rate_matrix(theta_of(t)) * theta_rate_of(t);
    CHECK((omega_fd - omega).norm() < 1e-8);  // central difference O(h²) ≈ 1e-10 × |θ'''|; 1e-8 margin
    // Inverse map recovers the Euler rates.
    CHECK((euler123_rates_from_body_angular_velocity(theta_of(t), omega) - theta_rate_of(t)).norm() < 1e-12);
  }
}

TEST_CASE("angular acceleration from T, Tdot, Tddot (eq. 2.4) matches d/dt of omega", "[unit][rotation]") {
  const double h = 1e-4;
  auto tm = [](double t) { return euler123_to_matrix(theta_of(t)); };
  auto omega = [](double t) { return Vec3(euler123_rate_matrix(theta_of(t)) * theta_rate_of(t)); };
  for (double t : {0.3, 1.7, 4.4}) {
    const Mat3 tdot = (tm(t + h) - tm(t - h)) / (2 * h);
    const Mat3 tddot = (tm(t + h) - 2 * tm(t) + tm(t - h)) / (h * h);
    const Vec3 alpha_formula = body_angular_acceleration(tm(t), tdot, tddot);
    const Vec3 alpha_fd = (omega(t + h) - omega(t - h)) / (2 * h);
    CHECK((alpha_formula - alpha_fd).norm() < 1e-6);  // FD second derivative: O(h²)+O(ε/h²) ≈ 1e-8; margin
  }
}

TEST_CASE("matrix_rate and matrix_second_rate invert the angular velocity formulas", "[unit][rotation]") {
  const Mat3 t = euler123_to_matrix({0.5, -0.2, 1.3});
  const Vec3 w(0.3, -1.1, 0.6), wd(-0.4, 0.2, 0.9);
  CHECK((body_angular_velocity(t, matrix_rate(t, w)) - w).norm() < 1e-14);
  CHECK((body_angular_acceleration(t, matrix_rate(t, w), matrix_second_rate(t, w, wd)) - wd).norm() < 1e-14);
  CHECK((spatial_angular_velocity(t, matrix_rate(t, w)) - t * w).norm() < 1e-14);  // ω_fixed = T ω_body
}

TEST_CASE("Euler rates are rejected at gimbal lock", "[unit][rotation]") {
  CHECK_THROWS_WITH(euler123_rates_from_body_angular_velocity({0.0, M_PI / 2, 0.0}, {0.1, 0, 0}),
                    Catch::Contains("theta2"));
}

TEST_CASE("elementary rotations are the explicit matrices T_ab, v_a = T_ab v_b", "[unit][rotation]") {
  const double a = 0.7, c = std::cos(a), s = std::sin(a);
  Mat3 rx, ry, rz;
  rx << 1, 0, 0, 0, c, -s, 0, s, c;
  ry << c, 0, s, 0, 1, 0, -s, 0, c;
  rz << c, -s, 0, s, c, 0, 0, 0, 1;
  CHECK(rotation_x(a) == rx);  // the same cos/sin in the same places: exact
  CHECK(rotation_y(a) == ry);
  CHECK(rotation_z(a) == rz);
  // Right-hand rule: a quarter turn about z carries b's x axis onto a's y axis, and so on round.
  // Tolerance 1e-16: cos(π/2) in doubles is 6.1e-17, not 0.
  CHECK((rotation_z(M_PI / 2) * Vec3::UnitX() - Vec3::UnitY()).norm() < 1e-16);
  CHECK((rotation_x(M_PI / 2) * Vec3::UnitY() - Vec3::UnitZ()).norm() < 1e-16);
  CHECK((rotation_y(M_PI / 2) * Vec3::UnitZ() - Vec3::UnitX()).norm() < 1e-16);
  // Rotations about one axis add: 1e-15 is a few roundings of entries of size 1.
  CHECK((rotation_y(0.4) * rotation_y(-1.3) - rotation_y(-0.9)).norm() < 1e-15);
  CHECK((rotation_x(a) * rotation_x(-a) - Mat3::Identity()).norm() < 1e-15);
}

TEST_CASE("elementary rotations equal Eigen's AngleAxisd bit for bit while cos a >= 0", "[unit][rotation]") {
  // AngleAxisd puts (1 − c) + c on the diagonal entry of the axis: exactly 1 for c >= 0, possibly
  // 1 − 2⁻⁵³ for c < 0. Every other entry is the same cos/sin, so for |a| <= π/2 (the beam's
  // twists and arc turns, which used AngleAxisd) the matrices are identical.
  int differing = 0;
  for (double a = -M_PI / 2; a <= M_PI / 2; a += 1e-4) {
    differing += rotation_x(a) != Eigen::AngleAxisd(a, Vec3::UnitX()).toRotationMatrix();
    differing += rotation_y(a) != Eigen::AngleAxisd(a, Vec3::UnitY()).toRotationMatrix();
    differing += rotation_z(a) != Eigen::AngleAxisd(a, Vec3::UnitZ()).toRotationMatrix();
  }
  CHECK(differing == 0);  // exact: no tolerance
}
