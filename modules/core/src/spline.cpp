#include "fowtsim/core/spline.hpp"

#include <utility>

#include "fowtsim/core/interpolation.hpp"

namespace fowtsim {

std::vector<double> natural_spline_second_derivatives(std::span<const double> x, std::span<const double> y) {
  const std::size_t n = x.size();
  std::vector<double> m(n, 0.0);
  if (n < 3) return m;
  std::vector<double> diag(n, 1.0), upper(n, 0.0), rhs(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
    const double lower = h0 / 6.0;
    diag[i] = (h0 + h1) / 3.0;
    upper[i] = h1 / 6.0;
    rhs[i] = (y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0;
    // Forward elimination with row i−1 (row 0 is the identity row m0 = 0).
    const double w = lower / diag[i - 1];
    diag[i] -= w * upper[i - 1];
    rhs[i] -= w * rhs[i - 1];
  }
  for (std::size_t i = n - 2; i >= 1; --i) {
    m[i] = (rhs[i] - upper[i] * m[i + 1]) / diag[i];
  }
  return m;
}

NaturalCubicSpline::NaturalCubicSpline(std::vector<double> x, std::vector<double> y)
    : x_(std::move(x)), y_(std::move(y)), m_(natural_spline_second_derivatives(x_, y_)) {}

double NaturalCubicSpline::operator()(double xq) const {
  return natural_spline_value(x_, y_, m_, bracket_index(x_, xq), xq);
}

}  // namespace fowtsim
