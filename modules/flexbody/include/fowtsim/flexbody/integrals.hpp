#pragma once
// The integrals of a slender body that the seed's equations of motion need, as line integrals
// along the axis (thin-beam, Sec. 4.1), for shapes bending in one plane (u along z):
//   M_q  = ∫ m u_i u_j dx           generalised mass (elastic block of the body mass matrix, Sec. 2)
//   K_q  = ∫ EI κ_i κ_j dx          generalised stiffness (K_gg of Sec. 2, Euler–Bernoulli)
//   ∫ m u_i dx, ∫ m x u_i dx        first moments: the translation–elastic and rotation–elastic
//                                   coupling blocks of the body mass matrix
//   K^T  = ∫ T ν_i ν_j dx           geometric stiffness, eq. 26
// Eq. 26 also has −[u_i ν_j T]_0^L. It vanishes here: u_i(0) = 0 (clamped root), and a tip load
// is carried by T on [0, L] (T(L) = T_L), i.e. the integration by parts of eq. 24 is taken to
// L⁺ where T = 0 — the delta term of eq. 22 and the jump of T cancel. This is the form the seed
// evaluates in Sec. 5.1 (K_MT = −M_t g ∫ ν_0² dx) and the one whose top-mass K^T gives the
// Euler buckling load, K_q + K^T = 0 at M_t g = P_cr = π²EI/(4L²).
#include "fowtsim/flexbody/axial_force.hpp"
#include "fowtsim/flexbody/quadrature.hpp"
#include "fowtsim/flexbody/shape_functions.hpp"

#include <Eigen/Dense>
#include <vector>

namespace fowtsim::flexbody {

// The shapes evaluated once at the quadrature points; every integral below is a weighted sum.
struct SampledBody {
  std::vector<QuadraturePoint> points;
  Eigen::MatrixXd u, nu, kappa;  // (point, shape)
};

SampledBody sample(const std::vector<QuadraturePoint>& points,
                   const std::vector<ShapeFunction>& shapes);

Eigen::MatrixXd generalized_mass(const SampledBody& body);
Eigen::MatrixXd generalized_stiffness(const SampledBody& body);
Eigen::VectorXd mass_first_moment(const SampledBody& body);  // ∫ m u_i dx   [kg]
Eigen::VectorXd mass_axial_moment(const SampledBody& body);  // ∫ m x u_i dx [kg m]
Eigen::MatrixXd geometric_stiffness(const SampledBody& body, const AxialForce& axial_force);

}  // namespace fowtsim::flexbody
