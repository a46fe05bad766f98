#pragma once
// Equations of motion of one Rayleigh–Ritz body on a hub spinning in the body's bending plane with
// a prescribed Ω(t), α(t) (the seed's Sec. 5.2, Kane's beam), derived from the seed's formulation
// for this planar case.
//
// Kinematics. Hub frame rotating about z with the hub, origin on the axis; the root is clamped at
// x_h = r (root_radius) on the hub frame's x axis, the body runs along x (x ∈ [0, L] from the
// root) and deflects in the plane of rotation: v(x, t) = Σ_j q_j u_j(x) along y (Sec. 4.1, with the
// thin-beam assumption u_x = x: no axial displacement). A point is at s_P = [r + x, v, 0]; eq. 18
// with a fixed hub origin (a = 0), ω = Ω e_z and ω̇ = α e_z gives
//   a_P = ω × (ω × s_P) + 2 ω × ṡ_P + ω̇ × s_P + s̈_P,
//   a_P·e_y = v̈ − Ω² v + α (r + x),   a_P·e_x = −Ω² (r + x) − 2 Ω v̇ − α v.
// Equations. The generalised force of the inertial load p = −m a_P on shape j is ∫ u_j p·e_y dx
// (eq. 4, virtual work of Sec. 2.3), the elastic force is −K_q q (eq. 10). The body keeps x fixed,
// so the axial inertial load p_x = −m a_P·e_x does no work: the seed's correction of Sec. 4.2
// (eqs. 21–26) adds it back as −K^T q with K^T_ij = ∫ T ν_i ν_j dx (eq. 26, boundary term zero:
// u(0) = 0 and T(L) = 0) and T(x) = ∫_x^L p_x. Kept to first order in q, p_x = m Ω² (r + x) (the
// Coriolis and α v parts are O(q) and would enter eq. 22 multiplied by ν: O(q²)), hence
// T = Ω² ∫_x^L m (r + s) ds and K^T = Ω² G with G the centrifugal stiffness per unit Ω²
// (centrifugal_axial_force with Ω = 1). Altogether
//   M_q q̈ + [K_q + Ω² (G − M_q)] q = −α b,    b_j = ∫ m (r + x) u_j dx,
// where −Ω² M_q is the in-plane centrifugal softening (the −Ω² v of a_P·e_y) and −α b the Euler
// load of the hub's angular acceleration. Without the correction (geometric_stiffening = false,
// G = 0) the stiffness K_q − Ω² M_q loses definiteness once Ω exceeds the first non-rotating
// frequency, the divergence the seed reports in Sec. 5.2.
#include "fowtsim/flexbody/integrals.hpp"
#include "fowtsim/flexbody/quadrature.hpp"
#include "fowtsim/flexbody/shape_functions.hpp"
#include "fowtsim/flexbody/stations.hpp"

#include <Eigen/Dense>
#include <vector>

namespace fowtsim::flexbody {

struct SpinningBeamOptions {
  double root_radius = 0.0;           // r: hub axis to root [m]
  bool geometric_stiffening = true;   // include K^T = Ω² G (eq. 26)
  QuadratureRule rule{};
};

class SpinningBeam {
 public:
  SpinningBeam(const BeamStations& stations, const std::vector<ShapeFunction>& shapes,
               const SpinningBeamOptions& options = {});

  // q̈ from the equation above at hub speed Ω and acceleration α.
  Eigen::VectorXd acceleration(const Eigen::VectorXd& q, double rate, double angular_acceleration) const;

  // Eigenvalues ω² [rad²/s²] of M_q⁻¹ [K_q + Ω² (G − M_q)] at constant Ω, ascending: the squared
  // rotating frequencies of the free in-plane vibration about q = 0 (negative: divergent).
  Eigen::VectorXd rotating_frequencies_squared(double rate) const;

  double tip_deflection(const Eigen::VectorXd& q) const { return tip_.dot(q); }  // v(L) [m]
  int size() const { return static_cast<int>(tip_.size()); }

  const Eigen::MatrixXd& mass() const { return mass_; }                     // M_q
  const Eigen::MatrixXd& stiffness() const { return stiffness_; }           // K_q
  const Eigen::MatrixXd& centrifugal_stiffness() const { return centrifugal_; }  // G (0 if off)
  const Eigen::VectorXd& euler_load() const { return euler_load_; }         // b

 private:
  Eigen::MatrixXd mass_, stiffness_, centrifugal_;
  Eigen::VectorXd euler_load_, tip_;
  Eigen::LLT<Eigen::MatrixXd> mass_llt_;
};

}  // namespace fowtsim::flexbody
