#include "fowtsim/flexbody/quadrature.hpp"

#include "fowtsim/core/error.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

namespace fowtsim::flexbody {
namespace {

[[noreturn]] void bad(const std::string& what, const std::string& message) {
  throw InputError({"flexbody", std::nullopt, what, "give stations from x = 0 to L, increasing"},
                   message);
}

void validate(const BeamStations& s, const QuadratureRule& rule) {
  const std::size_t n = s.x.size();
  if (n < 2) bad("stations", "a body needs at least 2 stations");
  if (s.m.size() != n || s.EI.size() != n) bad("stations", "x, m and EI differ in length");
  if (s.x.front() != 0.0) bad("x", "the first station must be the root, x = 0");
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0 && !(s.x[i] > s.x[i - 1])) bad("x", "stations must be strictly increasing");
    if (!(s.m[i] >= 0.0)) bad("m", "mass per length must be >= 0");
    if (!(s.EI[i] > 0.0)) bad("EI", "bending stiffness must be > 0");
  }
  if (rule.panels < 1 || rule.points < 1) bad("quadrature rule", "panels and points must be >= 1");
}

}  // namespace

// Newton on P_n from the Chebyshev-like guess cos(π(i + 3/4)/(n + 1/2)); converges to machine
// precision in a few steps.
std::vector<std::pair<double, double>> gauss_legendre(int n) {
  std::vector<std::pair<double, double>> nodes;
  for (int i = 0; i < n; ++i) {
    double t = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = t;  // P_0, P_1; recurrence (k+1) P_{k+1} = (2k+1) t P_k − k P_{k−1}
      for (int k = 1; k < n; ++k) {
        const double p2 = ((2.0 * k + 1.0) * t * p1 - k * p0) / (k + 1.0);
        p0 = p1;
        p1 = p2;
      }
      dp = n * (t * p1 - p0) / (t * t - 1.0);
      const double dt = p1 / dp;
      t -= dt;
      if (std::abs(dt) < 1e-16) break;
    }
    nodes.emplace_back(t, 2.0 / ((1.0 - t * t) * dp * dp));
  }
  return nodes;
}

std::vector<QuadraturePoint> quadrature_points(const BeamStations& s, const QuadratureRule& rule) {
  validate(s, rule);
  std::vector<QuadraturePoint> out;
  const std::size_t n = s.x.size();
  if (rule.kind == QuadratureRule::Kind::StationTrapezoid) {
    for (std::size_t i = 0; i < n; ++i) {
      const double left = i > 0 ? s.x[i] - s.x[i - 1] : 0.0;
      const double right = i + 1 < n ? s.x[i + 1] - s.x[i] : 0.0;
      out.push_back({s.x[i], 0.5 * (left + right), s.m[i], s.EI[i]});
    }
    return out;
  }
  const auto gl = gauss_legendre(rule.points);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double h = (s.x[i + 1] - s.x[i]) / rule.panels;
    for (int p = 0; p < rule.panels; ++p) {
      const double mid = s.x[i] + (p + 0.5) * h;
      for (const auto& [t, w] : gl) {
        const double x = mid + 0.5 * h * t;
        const double f = (x - s.x[i]) / (s.x[i + 1] - s.x[i]);  // linear properties (stations.hpp)
        out.push_back({x, 0.5 * h * w, s.m[i] + f * (s.m[i + 1] - s.m[i]),
                       s.EI[i] + f * (s.EI[i + 1] - s.EI[i])});
      }
    }
  }
  return out;
}

}  // namespace fowtsim::flexbody
