#include "fowtsim/core/error.hpp"
#include "fowtsim/flexbody/shape_functions.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace fowtsim::flexbody;

namespace {

// ν and κ against central differences of u and ν. Step L·1e-5: truncation (h²/6)·u''' ~ 1e-10·(β/L)³L²
// and round-off 1e-16/h ~ 1e-11·L, so 1e-7 relative to the derivative's scale holds for β <= 11.
void check_derivatives(const ShapeFunction& f, double length, double scale) {
  const double h = 1e-5 * length;
  for (double t : {0.05, 0.3, 0.5, 0.77, 0.95}) {
    const double x = t * length;
    const ShapeValue v = f(x);
    CHECK(v.nu == Approx((f(x + h).u - f(x - h).u) / (2 * h)).margin(1e-7 * scale / length));
    CHECK(v.kappa == Approx((f(x + h).nu - f(x - h).nu) / (2 * h)).margin(1e-7 * scale * scale / (length * length)));
  }
  // Clamped root and unit tip (exact by construction: to rounding).
  CHECK(f(0.0).u == Approx(0.0).margin(1e-12));
  CHECK(f(0.0).nu == Approx(0.0).margin(1e-12 * scale / length));
  CHECK(f(length).u == Approx(1.0).epsilon(1e-13));
}

}  // namespace

TEST_CASE("Shape functions: slope and curvature are the derivatives, root clamped, tip 1", "[unit]") {
  const double L = 60.0;
  check_derivatives(cosine_shape(L), L, 1.0);
  check_derivatives(polynomial_shape({0.7004, 2.1963, -5.6202, 6.2275, -2.504}, L), L, 20.0);
  for (int j = 1; j <= 4; ++j) check_derivatives(clamped_free_mode(j, L), L, clamped_free_beta(j) * 2);
  check_derivatives(clamped_free_mode(2, L, 0.8), L, 10.0);
}

TEST_CASE("Eq. 32: the classic cantilever roots, a moment-free tip, the top-mass equation", "[unit]") {
  // β_j L of the clamped-free uniform beam (1 + cosh β cos β = 0), to the 9 digits tabulated in
  // Blevins, Formulas for natural frequency and mode shape, Table 8-1.
  const std::vector<double> beta{1.875104069, 4.694091133, 7.854757438, 10.99554073};
  for (int j = 1; j <= 4; ++j) {
    CHECK(clamped_free_beta(j) == Approx(beta[j - 1]).epsilon(1e-9));  // table rounding
    CHECK(clamped_free_mode(j, 10.0)(10.0).kappa == Approx(0.0).margin(1e-10));  // u''(L) = 0
  }
  // With a top mass: β solves eq. 32's equation and drops (heavier tip, lower frequency).
  const double mu = 0.5;
  for (int j = 1; j <= 3; ++j) {
    const double b = clamped_free_beta(j, mu);
    const double r = 1 + std::cosh(b) * std::cos(b) - b * mu * (std::sin(b) * std::cosh(b) - std::cos(b) * std::sinh(b));
    CHECK(std::abs(r) / std::cosh(b) < 1e-12);  // residual scaled as solved
    CHECK(b < beta[j - 1]);
  }
}

TEST_CASE("Shape functions refuse input that is not a body", "[unit]") {
  CHECK_THROWS_AS(polynomial_shape({1.0, 1.0, 0.0, 0.0, 0.0}, 10.0), fowtsim::InputError);
  CHECK_THROWS_AS(cosine_shape(0.0), fowtsim::InputError);
  CHECK_THROWS_AS(clamped_free_beta(0), fowtsim::InputError);
  CHECK_THROWS_AS(clamped_free_beta(1, -1.0), fowtsim::InputError);
}
