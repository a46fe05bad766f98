#include "fowtsim/flexbody/torsion.hpp"

#include "fowtsim/core/error.hpp"
#include "fowtsim/flexbody/integrals.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace fowtsim::flexbody {

ShapeFunction torsion_sine_shape(int j, double L) {
  if (j < 1 || !(L > 0.0))
    throw InputError({"flexbody", std::nullopt, "torsion shape", "j ≥ 1, L > 0"}, "bad torsion shape");
  const double b = std::numbers::pi / 2 + (j - 1) * std::numbers::pi;
  return ShapeFunction("torsion sin " + std::to_string(j), [b, L](double x) {
    const double a = b * x / L, k = b / L;
    return ShapeValue{std::sin(a), k * std::cos(a), -k * k * std::sin(a)};
  });
}

TorsionModel torsion_model(const BeamStations& stations, const std::vector<ShapeFunction>& shapes,
                           const QuadratureRule& rule) {
  const SampledBody body = sample(quadrature_points(stations, rule), shapes);
  TorsionModel out;
  out.M = generalized_mass(body);  // ∫ (m = j_G) ν_x ν_x
  Eigen::VectorXd wk(static_cast<Eigen::Index>(body.points.size()));
  for (Eigen::Index k = 0; k < wk.size(); ++k) {
    const QuadraturePoint& p = body.points[static_cast<std::size_t>(k)];
    wk(k) = p.w * p.EI;  // GK_t
  }
  out.K = body.nu.transpose() * wk.asDiagonal() * body.nu;  // ∫ GK_t κ_x κ_x
  out.tip.resize(static_cast<Eigen::Index>(shapes.size()));
  for (std::size_t j = 0; j < shapes.size(); ++j) out.tip(static_cast<Eigen::Index>(j)) = shapes[j](stations.length()).u;
  return out;
}

}  // namespace fowtsim::flexbody
