#pragma once
// Quadrature over a station table. Every integral of the body (Sec. 2 and 4 of the seed) is
// ∫_0^L f(x) dx with f built from m, EI and the shape functions, so one point set serves all.
//
// GaussLegendre: each station interval is split into `panels` equal panels, each integrated by
// `points`-point Gauss–Legendre. m and EI are linear on an interval, so the rule is exact when the
// shape functions are polynomials of degree <= points − 1 (ElastoDyn's degree-6 polynomials with
// the default 8 points); for the eq. 32 modes (entire functions with scale β/L) the error falls
// as (h β/L)^(2·points) and is measured in quadrature_tests.cpp (below 1e-13 relative for the
// defaults on β <= 11).
// StationTrapezoid: the trapezoid rule on the stations themselves, O(h²) — what welib's
// GMBeam/GKBeam use; kept to reproduce its published numbers (welib_uniform_beam_tests.cpp)
// and to let a caller match a code that integrates on its stations.
#include "fowtsim/flexbody/stations.hpp"

#include <utility>
#include <vector>

namespace fowtsim::flexbody {

struct QuadraturePoint {
  double x;   // [m]
  double w;   // weight [m]
  double m;   // mass per length at x [kg/m]
  double EI;  // bending stiffness at x [N m^2]
};

struct QuadratureRule {
  enum class Kind { GaussLegendre, StationTrapezoid };
  Kind kind = Kind::GaussLegendre;
  int panels = 8;  // per station interval (GaussLegendre only)
  int points = 8;  // per panel (GaussLegendre only)
};

// Nodes t and weights w of n-point Gauss–Legendre on [−1, 1] (exact for degree <= 2n − 1).
std::vector<std::pair<double, double>> gauss_legendre(int n);

// Throws InputError for a table that is not a body (fewer than 2 stations, sizes differ, x not
// starting at 0 or not increasing, negative m or non-positive EI) or a rule with panels/points < 1.
std::vector<QuadraturePoint> quadrature_points(const BeamStations& stations,
                                               const QuadratureRule& rule = {});

}  // namespace fowtsim::flexbody
