#pragma once
// Where a blade's integrals are evaluated, with its properties there (ElastoDyn's AdjBlMs, AdjFlSt
// and AdjEdSt applied, twist in radians). Two rules over x = r − HubRad ∈ [0, L]:
//  * Gauss: quadrature.hpp's Gauss–Legendre on each station interval — m, EI and the twist are
//    linear there, so the integrals of the degree-6 polynomial shapes are exact up to the
//    twist's cos/sin (smooth within an interval); the converged value of each integral.
//  * ElastoDyn nodes: ElastoDyn's BldNodes equal elements, one point at each element's middle,
//    weight L/BldNodes, properties interpolated linearly from the stations to the node — the
//    midpoint rule ElastoDyn sums its blade mass, moments and generalised matrices with, so its
//    printed numbers (summary file) are reproduced to their digits.
//  * Spans: the given points, weight 0 — not a rule, the places where shapes are wanted.
#include "fowtsim/flexbody/elastodyn_blade.hpp"
#include "fowtsim/flexbody/quadrature.hpp"

#include <vector>

namespace fowtsim::flexbody {

struct BladePoint {
  double x;        // distance from the blade root [m]
  double w;        // weight [m]
  double m;        // mass per length, × AdjBlMs [kg/m]
  double EI_flap;  // flap stiffness, × AdjFlSt [N m^2]
  double EI_edge;  // edge stiffness, × AdjEdSt [N m^2]
  double twist;    // structural twist θ [rad]
};

struct BladeRule {
  enum class Kind { Gauss, ElastoDynNodes, Spans };
  Kind kind = Kind::Gauss;
  QuadratureRule gauss{};   // Gauss only
  int elastodyn_nodes = 17;  // ElastoDynNodes only: BldNodes (17 in the NREL 5MW ElastoDyn deck)
  std::vector<double> spans;  // Spans only: points at these x ∈ [0, L] with weight 0 (to evaluate shapes) [m]
};

// Validates the blade (validate()) and the rule (InputError for elastodyn_nodes < 1 or a span outside [0, L]).
std::vector<BladePoint> blade_points(const ElastoDynBlade& blade, const BladeRule& rule = {});

// The blade's station table in flexbody's form (x = BlFract L, m × AdjBlMs, EI = flap × AdjFlSt),
// for the axial-force distributions of axial_force.hpp.
BeamStations blade_stations(const ElastoDynBlade& blade);

// Structural twist θ(x) [rad], linear between stations (as ElastoDyn interpolates StrcTwst).
double blade_twist(const ElastoDynBlade& blade, double x);

}  // namespace fowtsim::flexbody
