#pragma once
// A blade's three Rayleigh–Ritz shapes (flap 1, flap 2, edge 1) sampled at its integration points,
// as ElastoDyn builds them (its "twisted shape functions"; the formulation was read from OpenFAST
// ElastoDyn's coefficient routine, this is an implementation of it, not a translation). Each shape bends about ONE
// principal axis of the section, and that axis turns with the structural twist θ(x). So the mode
// polynomial φ(x) gives the curvature magnitude, κ = φ''(x), along the principal direction at x:
//   flap mode: Φ'' = φ''(x) e_f(θ),  e_f = ( cos θ, −sin θ)
//   edge mode: Φ'' = φ''(x) e_e(θ),  e_e = ( sin θ,  cos θ)
// in the blade axes (out-of-plane "flap" axis, in-plane "edge" axis, at zero pitch), with θ =
// StrcTwst in ElastoDyn's sign. The displacement follows by integrating twice from the clamped root,
//   Φ'(x) = ∫_0^x Φ'' ds,   Φ(x) = ∫_0^x (x − s) Φ'' ds,
// so a flap mode of a twisted blade also moves in-plane (ElastoDyn's "TwistedSF", Φ and Ψ parts).
// Here those two integrals are evaluated to rounding (8-point Gauss between stations, where θ is
// linear); ElastoDyn integrates them by its midpoint rule on the blade nodes.
//
// `untwisted` is the other common choice: φ itself along the fixed flap or edge axis (as a code
// would take shapes from an untwisted beam). Its curvature then has components on both principal
// axes, and eq. 20 couples flap and edge through the stiffness instead of the mass (rr_blade.hpp).
#include "fowtsim/flexbody/blade_points.hpp"

#include <Eigen/Dense>

namespace fowtsim::flexbody {

enum class BladeShapeFrame { twisted, untwisted };

inline constexpr int kBladeShapes = 3;  // column order: flap 1, flap 2, edge 1

struct SampledBlade {
  std::vector<BladePoint> points;
  // (point, shape):
  Eigen::MatrixXd u_flap, u_edge;    // displacement along the blade's flap / edge axis per unit q [-]
  Eigen::MatrixXd nu_flap, nu_edge;  // slopes of the same [1/m]
  Eigen::MatrixXd kappa_f, kappa_e;  // curvature components along the principal e_f, e_e at x [1/m^2]
  Eigen::MatrixXd phi, dphi;         // the polynomial φ and φ' themselves [-], [1/m] (ElastoDyn's
                                     // per-mode generalised mass and centrifugal stiffness use them)
};

// Throws InputError for an invalid blade or rule, or shape coefficients that do not sum to 1.
SampledBlade sample_blade(const ElastoDynBlade& blade, const BladeRule& rule = {},
                          BladeShapeFrame frame = BladeShapeFrame::twisted);

}  // namespace fowtsim::flexbody
