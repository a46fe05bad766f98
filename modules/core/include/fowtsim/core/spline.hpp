#pragma once
// Natural cubic spline through (x_i, y_i), x strictly increasing (Press et al., Numerical Recipes
// §3.3): cubic on each interval, continuous first and second derivatives, y'' = 0 at both ends.
// Outside [x_0, x_{n−1}] the end intervals' cubics are extended.
#include <cstddef>
#include <span>
#include <vector>

namespace fowtsim {

// Second derivatives m_i = y''(x_i) of the natural spline: the tridiagonal system of continuous
// first derivatives with m_0 = m_{n−1} = 0, solved by the Thomas algorithm. All zero for n < 3
// (the straight line).
std::vector<double> natural_spline_second_derivatives(std::span<const double> x, std::span<const double> y);

// The spline on [x_i, x_{i+1}] with second derivatives m. Inline: the airfoil polars are
// evaluated at every residual call of the induction solver.
inline double natural_spline_value(std::span<const double> x, std::span<const double> y,
                                   std::span<const double> m, std::size_t i, double xq) {
  const double h = x[i + 1] - x[i];
  const double a = (x[i + 1] - xq) / h, b = (xq - x[i]) / h;
  return a * y[i] + b * y[i + 1] + ((a * a * a - a) * m[i] + (b * b * b - b) * m[i + 1]) * h * h / 6.0;
}

// One curve y(x) with its second derivatives; at least 2 points.
class NaturalCubicSpline {
 public:
  NaturalCubicSpline(std::vector<double> x, std::vector<double> y);
  double operator()(double xq) const;

 private:
  std::vector<double> x_, y_, m_;
};

}  // namespace fowtsim
