#pragma once
// Torsion of a straight body about its axis x (seed Sec. 4.3 and 5.3): shape functions give the
// twist angle ν_x^j(x) [rad per unit coordinate] and its rate κ_x^j = ∂ν_x^j/∂x [rad/m];
//   M_ij = ∫ j_G ν_x^i ν_x^j dx       (eq. 31, the section polar inertia j_G [kg m])
//   K_ij = ∫ GK_t κ_x^i κ_x^j dx      (eq. 20's torsion term, GK_t [N m²])
// A ShapeFunction here carries u = ν_x, nu = κ_x, kappa = ∂κ_x/∂x, and the station table m = j_G,
// EI = GK_t (same linear interpolation and quadrature as bending).
#include "fowtsim/flexbody/quadrature.hpp"
#include "fowtsim/flexbody/shape_functions.hpp"

#include <Eigen/Dense>
#include <vector>

namespace fowtsim::flexbody {

// Sec. 5.3: the torsion modes of a uniform clamped-free shaft, ν_x^j = sin(β_j x̃),
// β_j = π/2 + (j − 1)π, ω_j = (c/L) β_j, c = sqrt(GK_t/j_G). ν_x^j(L) = (−1)^(j−1).
ShapeFunction torsion_sine_shape(int j, double length);

struct TorsionModel {
  Eigen::MatrixXd M, K;  // [kg m²], [N m]
  Eigen::VectorXd tip;   // ν_x^j(L): twist at the free end per unit coordinate; also the generalised
                         // force per unit tip moment (virtual work M_x δν_x(L))
};

// `stations`: x [m], m = j_G [kg m], EI = GK_t [N m²].
TorsionModel torsion_model(const BeamStations& stations, const std::vector<ShapeFunction>& shapes,
                           const QuadratureRule& rule = {});

}  // namespace fowtsim::flexbody
