#include "fowtsim/waves/dispersion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::waves {

double wavenumber(double omega, double depth, double g) {
  if (!(std::isfinite(omega) && omega >= 0.0))
    throw InputError({"waves.dispersion", std::nullopt, "omega", "a frequency >= 0"},
                     fmt::format("angular frequency must be finite and >= 0, found {}", omega));
  if (!(depth > 0.0))
    throw InputError({"waves.dispersion", std::nullopt, "depth_m", "a depth > 0 (inf for deep water)"},
                     fmt::format("water depth must be > 0, found {}", depth));
  if (!(std::isfinite(g) && g > 0.0))
    throw InputError({"waves.dispersion", std::nullopt, "gravity_m_s2", ""},
                     fmt::format("gravity must be finite and > 0, found {}", g));
  if (omega == 0.0) return 0.0;
  if (std::isinf(depth)) return deep_water_wavenumber(omega, g);

  // x tanh x = y with x = k h, y = ω² h / g. Since tanh x < 1 and tanh x < x, the root lies above
  // max(y, √y); since tanh is increasing, x = y / tanh x ≤ y / tanh(lower bound).
  const double y = omega * omega * depth / g;
  double lo = std::max(y, std::sqrt(y));
  double hi = y / std::tanh(lo);
  if (!(hi > lo)) return lo / depth;  // tanh(lo) == 1 in double: deep water, x = y exactly

  // Fenton & McKee (1990), Coastal Engineering 14: x ≈ y (tanh y^{3/4})^{-2/3}, within 1.5 %.
  double x = std::clamp(y * std::pow(std::tanh(std::pow(y, 0.75)), -2.0 / 3.0), lo, hi);
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double t = std::tanh(x);
    const double f = x * t - y;
    if (f == 0.0) break;
    (f < 0.0 ? lo : hi) = x;
    const double slope = t + x * (1.0 - t * t);
    double next = x - f / slope;
    if (!(next >= lo && next <= hi)) next = 0.5 * (lo + hi);  // safeguard: bisect
    const bool converged = std::abs(next - x) <= 2.0 * std::numeric_limits<double>::epsilon() * x;
    x = next;
    if (converged || hi - lo <= 2.0 * std::numeric_limits<double>::epsilon() * x) break;
  }
  return x / depth;
}

}  // namespace fowtsim::waves
