// Natural cubic spline: the knots, the natural end conditions and values solved by hand.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/core/spline.hpp"

using namespace fowtsim;

TEST_CASE("natural spline of three points matches the hand-solved system", "[unit][spline]") {
  // x = 0, 1, 2; y = 0, 1, 0: (h0 + h1)/3 m1 = (y2 − y1)/h1 − (y1 − y0)/h0 gives m1 = −3, so
  // y(0.5) = 0.5 + (0.5³ − 0.5)(−3)/6 = 0.6875 and, by symmetry, y(1.5) too.
  const std::vector<double> x{0.0, 1.0, 2.0}, y{0.0, 1.0, 0.0};
  const std::vector<double> m = natural_spline_second_derivatives(x, y);
  CHECK(m[0] == 0.0);  // natural ends are set, not solved: exact
  CHECK(m[2] == 0.0);
  CHECK(m[1] == Approx(-3.0).margin(1e-15));  // two roundings of numbers of size 1
  const NaturalCubicSpline spline(x, y);
  CHECK(spline(0.5) == Approx(0.6875).margin(1e-15));
  CHECK(spline(1.5) == Approx(0.6875).margin(1e-15));
  for (std::size_t i = 0; i < x.size(); ++i) CHECK(spline(x[i]) == Approx(y[i]).margin(1e-15));  // through the knots
}

TEST_CASE("natural spline is exact on straight lines and the line for two points", "[unit][spline]") {
  const std::vector<double> x{-2.0, -0.5, 0.0, 1.5, 4.0};
  std::vector<double> y;
  for (double xi : x) y.push_back(0.3 * xi - 1.2);
  const NaturalCubicSpline spline(x, y);
  // m = 0 up to round-off in the right-hand sides: 1e-14 on values of size 1.
  for (double xq : {-2.0, -1.1, 0.2, 2.9, 4.0, 5.0}) CHECK(spline(xq) == Approx(0.3 * xq - 1.2).margin(1e-14));
  const NaturalCubicSpline line({0.0, 2.0}, {1.0, 5.0});
  CHECK(line(0.5) == Approx(2.0).margin(1e-15));  // no interior knot: the chord, to one rounding
}

TEST_CASE("natural spline of sin on [0, pi] converges at fourth order", "[unit][spline]") {
  // sin'' vanishes at 0 and π, so the natural end conditions are the true ones and the error is
  // O(h⁴) up to the ends. Bound: 5/384 h⁴ max|sin''''|, the complete cubic spline's (Hall & Meyer
  // 1976), 7.9e-6 for h = π/20; measured 1.6e-6.
  constexpr int kIntervals = 20;
  const double h = std::numbers::pi / kIntervals;
  std::vector<double> x, y;
  for (int i = 0; i <= kIntervals; ++i) {
    x.push_back(i * h);
    y.push_back(std::sin(i * h));
  }
  const NaturalCubicSpline spline(x, y);
  double worst = 0.0;
  for (double xq = 0.0; xq <= std::numbers::pi; xq += 1e-3) worst = std::max(worst, std::abs(spline(xq) - std::sin(xq)));
  CHECK(worst < 5.0 / 384.0 * std::pow(h, 4));
}
