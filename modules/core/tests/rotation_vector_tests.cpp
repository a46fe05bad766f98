// Exponential map of SO(3) and its Jacobians, checked against Eigen's AngleAxis and against
// central finite differences (error O(h²) ≈ 1e-10 at h = 1e-5, hence the 1e-8 bounds).
#include <cmath>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include "fowtsim/core/rotation.hpp"
#include "fowtsim/core/rotation_vector.hpp"

using namespace fowtsim;

TEST_CASE("rotation_matrix agrees with Eigen AngleAxis and rotation_vector inverts it",
          "[unit][rotation]") {
  const Vec3 axis = Vec3(0.3, -0.5, 0.8).normalized();
  for (double a : {0.0, 1e-9, 1e-5, 0.3, 1.5, 3.0, 3.1, 3.14159}) {
    const Mat3 r = rotation_matrix(a * axis);
    const Mat3 ref = Eigen::AngleAxisd(a, axis).toRotationMatrix();
    CHECK((r - ref).norm() < 1e-14);                               // both exact to rounding
    CHECK((rotation_vector(r) - a * axis).norm() < 1e-9 * (1 + a));  // π-branch loses ~√ε·… only near π
  }
}

TEST_CASE("right Jacobian and its inverse match finite differences", "[unit][rotation]") {
  const double h = 1e-5;
  for (const Vec3& phi : {Vec3(0.0, 0.0, 0.0), Vec3(1e-6, 2e-6, 0.0), Vec3(0.4, -0.2, 0.9),
                          Vec3(-1.9, 1.0, 0.5)}) {
    const Mat3 jr = right_jacobian(phi);
    const Mat3 jinv = right_jacobian_inverse(phi);
    CHECK((jr * jinv - Mat3::Identity()).norm() < 1e-12);  // analytic inverse pair
    const Mat3 r = rotation_matrix(phi);
    for (int k = 0; k < 3; ++k) {
      const Vec3 e = Vec3::Unit(k);
      // exp((φ + h e)~) = exp(φ̃) exp((J_r h e)~) + O(h²)
      const Vec3 col = (rotation_vector(r.transpose() * rotation_matrix(phi + h * e)) -
                        rotation_vector(r.transpose() * rotation_matrix(phi - h * e))) / (2 * h);
      CHECK((col - jr.col(k)).norm() < 1e-8);
      // log(exp(φ̃) exp(h ẽ)) = φ + J_r⁻¹ h e + O(h²)
      const Vec3 dlog = (rotation_vector(r * rotation_matrix(h * e)) -
                         rotation_vector(r * rotation_matrix(-h * e))) / (2 * h);
      CHECK((dlog - jinv.col(k)).norm() < 1e-8);
    }
  }
}

TEST_CASE("Wiener-Milenkovic parameters are 4 tan(phi/4) along the axis", "[unit][rotation]") {
  const Vec3 axis = Vec3(1.0, 2.0, -2.0) / 3.0;
  CHECK((wiener_milenkovic(rotation_matrix(2.0 * axis)) - 4.0 * std::tan(0.5) * axis).norm() <
        1e-14);
  CHECK(wiener_milenkovic(Mat3::Identity()).norm() == 0.0);
}

TEST_CASE("series and closed forms agree on both sides of their switch-over angles",
          "[unit][rotation]") {
  // The small-angle factors are Taylor series below 0.5 rad (0.1 for the logarithm's sine) and
  // closed forms above. Reference: the closed forms in long double, exact to ~1e-19 here.
  const Vec3 axis = Vec3(0.3, -0.5, 0.8).normalized();
  for (double a : {1e-3, 0.0999, 0.1001, 0.2, 0.4999999, 0.5000001}) {
    const long double la = a;
    const long double sinc = std::sin(la) / la, cosc = (1 - std::cos(la)) / (la * la);
    const long double sinc_residual = (la - std::sin(la)) / (la * la * la);
    const long double jinv = 1 / (la * la) - (1 + std::cos(la)) / (2 * la * std::sin(la));
    const Mat3 p = skew(a * axis);
    const Mat3 exp_ref = Mat3::Identity() + double(sinc) * p + double(cosc) * p * p;
    const Mat3 jr_ref = Mat3::Identity() - double(cosc) * p + double(sinc_residual) * p * p;
    const Mat3 jinv_ref = Mat3::Identity() + 0.5 * p + double(jinv) * p * p;
    // Rounding of a few operations on O(1) entries: 1e-15.
    CHECK((rotation_matrix(a * axis) - exp_ref).norm() < 1e-15);
    CHECK((right_jacobian(a * axis) - jr_ref).norm() < 1e-15);
    CHECK((right_jacobian_inverse(a * axis) - jinv_ref).norm() < 1e-15);
    CHECK((rotation_vector(exp_ref) - a * axis).norm() < 1e-15 * (1 + a));
  }
}
