#include "fowtsim/flexbody/blade_points.hpp"

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/interpolation.hpp"

#include <numbers>
#include <string>

namespace fowtsim::flexbody {
namespace {

std::vector<double> scaled(const std::vector<double>& v, double factor) {
  std::vector<double> out(v);
  for (double& x : out) x *= factor;
  return out;
}

std::vector<double> station_x(const ElastoDynBlade& b) { return scaled(b.span_fraction, b.length()); }

BladePoint point_at(const ElastoDynBlade& b, const std::vector<double>& x, double xq, double w) {
  return {xq,
          w,
          b.mass_factor * interpolate_linear(x, b.mass_density, xq),
          b.flap_stiffness_factor * interpolate_linear(x, b.flap_stiffness, xq),
          b.edge_stiffness_factor * interpolate_linear(x, b.edge_stiffness, xq),
          blade_twist(b, xq)};
}

}  // namespace

BeamStations blade_stations(const ElastoDynBlade& b) {
  validate(b);
  return {station_x(b), scaled(b.mass_density, b.mass_factor), scaled(b.flap_stiffness, b.flap_stiffness_factor)};
}

double blade_twist(const ElastoDynBlade& b, double x) {
  return interpolate_linear(station_x(b), b.twist_deg, x) * std::numbers::pi / 180.0;
}

std::vector<BladePoint> blade_points(const ElastoDynBlade& b, const BladeRule& rule) {
  const BeamStations stations = blade_stations(b);
  std::vector<BladePoint> out;
  if (rule.kind == BladeRule::Kind::Gauss) {
    // Gauss points lie strictly inside the station intervals, where every property is linear.
    for (const QuadraturePoint& q : quadrature_points(stations, rule.gauss)) out.push_back(point_at(b, stations.x, q.x, q.w));
    return out;
  }
  if (rule.kind == BladeRule::Kind::Spans) {
    for (const double x : rule.spans) {
      if (!(x >= 0.0 && x <= b.length()))
        throw InputError({"flexbody.blade", std::nullopt, "span", "0 … the blade length"},
                         "a blade span of " + std::to_string(x) + " m lies outside the blade (0 … " + std::to_string(b.length()) + " m)");
      out.push_back(point_at(b, stations.x, x, 0.0));
    }
    return out;
  }
  if (rule.elastodyn_nodes < 1)
    throw InputError({"flexbody.blade", std::nullopt, "BldNodes", "give at least 1 blade node"}, "no blade nodes");
  const double h = b.length() / rule.elastodyn_nodes;
  for (int j = 0; j < rule.elastodyn_nodes; ++j) out.push_back(point_at(b, stations.x, (j + 0.5) * h, h));
  return out;
}

}  // namespace fowtsim::flexbody
