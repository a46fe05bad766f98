#include "fowtsim/core/interpolation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "fowtsim/core/error.hpp"

namespace fowtsim {

std::size_t bracket_index(std::span<const double> x, double xq) {
  if (x.size() < 2) return 0;
  const auto it = std::upper_bound(x.begin(), x.end(), xq);
  const auto i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - x.begin() - 1, 0));
  return std::min(i, x.size() - 2);
}

double interpolate_linear(std::span<const double> x, std::span<const double> y, double xq) {
  if (x.size() != y.size() || x.empty()) {
    throw InputError({"core.interpolation", {}, "", ""},
                     "interpolation table needs equal, non-zero sizes (x: " +
                         std::to_string(x.size()) + ", y: " + std::to_string(y.size()) + ")");
  }
  if (x.size() == 1 || xq <= x.front()) return y.front();
  if (xq >= x.back()) return y.back();
  const std::size_t i = bracket_index(x, xq);
  const double s = (xq - x[i]) / (x[i + 1] - x[i]);
  return lerp(y[i], y[i + 1], s);
}

void require_strictly_increasing(std::span<const double> x, const char* what) {
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (!(x[i] > x[i - 1])) {
      throw InputError({"core.interpolation", {}, what, "sort the table and remove repeats"},
                       std::string(what) + " must be strictly increasing (entry " +
                           std::to_string(i) + ")");
    }
  }
}

PeriodicStencil periodic_cubic_stencil(double t, double period, std::size_t samples) {
  if (!std::isfinite(t))
    throw NumericalError({"core.interpolation", std::nullopt, "time", "check the time handed to the lookup"},
                         "non-finite time in a periodic record lookup");
  const double dt = period / static_cast<double>(samples);
  const double tau = t - period * std::floor(t / period);  // [0, period] (period by round-off)
  const double u = tau / dt;
  const double whole = std::floor(u);
  const double s = u - whole;
  const std::size_t m = samples;
  const std::size_t j = static_cast<std::size_t>(whole) % m;
  PeriodicStencil ps;
  ps.index[0] = (j + m - 1) % m;
  ps.index[1] = j;
  ps.index[2] = (j + 1) % m;
  ps.index[3] = (j + 2) % m;
  // Lagrange basis on the nodes −1, 0, 1, 2 at s ∈ [0, 1).
  ps.weight[0] = -s * (s - 1.0) * (s - 2.0) / 6.0;
  ps.weight[1] = (s + 1.0) * (s - 1.0) * (s - 2.0) / 2.0;
  ps.weight[2] = -(s + 1.0) * s * (s - 2.0) / 2.0;
  ps.weight[3] = (s + 1.0) * s * (s - 1.0) / 6.0;
  return ps;
}

}  // namespace fowtsim
