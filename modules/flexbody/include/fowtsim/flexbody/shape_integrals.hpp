#pragma once
// The shape integrals of the seed's appendix A (eq. 37), from which the flexible-body mass matrix of
// eq. 2 is assembled at any deflection g without re-integrating (eq. 38, Shabana's invariants):
//   M = ∫ dm,  σ = ∫ s₀ dm,  σ_kl = ∫ s₀k s₀l dm,  Σ_kl = ∫ s₀k Φ_l dm (1 × n_f),
//   Ψ = ∫ Φ dm (3 × n_f),  Υ_kl = ∫ Φ_kᵀ Φ_l dm (n_f × n_f),  k, l = x, y, z (0, 1, 2 here),
// where s₀ [m] is a point's undeformed position in the body frame and Φ (3 × n_f) the shapes there
// (Φ_k its row k). Volume integrals become sums over mass points (thin beam: line integrals, Sec. 4.1).
#include "fowtsim/flexbody/integrals.hpp"

#include <Eigen/Dense>
#include <array>
#include <vector>

namespace fowtsim::flexbody {

struct MassPoint {
  double dm;                                  // mass [kg] (quadrature weight × m)
  Eigen::Vector3d s0;                         // undeformed position in the body frame [m]
  Eigen::Matrix<double, 3, Eigen::Dynamic> phi;  // shape values there, 3 × n_f [-]
};

struct ShapeIntegrals {
  double mass = 0.0;                                  // M [kg]
  Eigen::Vector3d sigma = Eigen::Vector3d::Zero();    // σ [kg m]
  Eigen::Matrix3d sigma2 = Eigen::Matrix3d::Zero();   // σ_kl [kg m²]
  std::array<std::array<Eigen::RowVectorXd, 3>, 3> Sigma;    // Σ_kl [kg m]
  Eigen::Matrix<double, 3, Eigen::Dynamic> Psi;               // Ψ [kg]
  std::array<std::array<Eigen::MatrixXd, 3>, 3> Upsilon;      // Υ_kl [kg]
  int shapes() const { return static_cast<int>(Psi.cols()); }
};

// Throws InputError if the points disagree on n_f.
ShapeIntegrals shape_integrals(const std::vector<MassPoint>& points);

// A straight thin beam along the body's x axis (s₀ = [x, 0, 0], COG on the mean line) whose
// sampled shapes u_j deflect along `direction` (e.g. e_z: the seed's u_z, Sec. 4.1, 6).
std::vector<MassPoint> straight_beam_mass_points(const SampledBody& body, const Eigen::Vector3d& direction);

}  // namespace fowtsim::flexbody
