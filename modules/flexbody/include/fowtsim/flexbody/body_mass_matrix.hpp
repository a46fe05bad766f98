#pragma once
// The mass matrix M' of one body in its own frame (seed Sec. 2.2, eq. 2), DOF order
// [v' (3), ω' (3), ġ (n_f)]:
//   M'_xx = M I₃,  M'_xθ = −∫ s̃ dm,  M'_xg = ∫ Φ dm,  M'_θθ = −∫ s̃ s̃ dm,  M'_θg = ∫ s̃ Φ dm,
//   M'_gg = ∫ Φᵀ Φ dm,  s = s₀ + Φ g,
// evaluated from the shape integrals with eq. 38: M'_xθ = −skew(σ + Ψ g), M'_gg = Υ_xx + Υ_yy + Υ_zz,
// M'_θθ from u_kl = σ_kl + (Σ_kl + Σ_lk) g + gᵀ Υ_kl g, M'_θg rows gᵀ(Υ_yz − Υ_zy) + Σ_yz − Σ_zy, …
// Plus the thin-beam corrections of Sec. 4: the section inertia j_G (eq. 31) and the axial-inertia
// terms of eqs. 28–29 that replace row/column 1.
#include "fowtsim/flexbody/axial_force.hpp"
#include "fowtsim/flexbody/integrals.hpp"
#include "fowtsim/flexbody/shape_integrals.hpp"

#include <Eigen/Dense>

namespace fowtsim::flexbody {

// Eq. 2 via eq. 38 at deflection g (n_f). Throws InputError if g's size is not n_f.
Eigen::MatrixXd body_mass_matrix(const ShapeIntegrals& si, const Eigen::VectorXd& g);

// Eq. 5's rigid body: mass [kg], COG ρ' from the origin [m], inertia J' about the origin [kg m²]:
// [M I, −M ρ̃; M ρ̃, J'] (6 × 6).
Eigen::Matrix<double, 6, 6> rigid_body_mass_matrix(double mass, const Eigen::Vector3d& cog,
                                                  const Eigen::Matrix3d& inertia_at_origin);

// Eq. 31 for a beam along x: adds ∫ j_G dx [kg m²] to M_44 (rotation about the axis), ∫ j_G ν_x^j dx
// to M_4(6+j) and ∫ ν_x^i j_G ν_x^j dx to M_(6+i)(6+j). `torsion_coupling` and `torsion_mass` may be
// empty (no torsion shapes: only the polar term). Throws InputError on size mismatch.
void add_section_inertia(Eigen::MatrixXd& M, double polar_inertia,
                         const Eigen::VectorXd& torsion_coupling = {},
                         const Eigen::MatrixXd& torsion_mass = {});

// Eqs. 28–29 for a straight beam along x whose sampled shapes deflect along z (as sampled in `body`)
// at deflection g: the concentrated section mass cannot move axially in the thin-beam model, so the
// axial inertia of a unit x acceleration, p_x = m, is carried by its equivalent transverse load
// (eq. 22) and replaces
//   M_15 = ∫ ν_z T dx,   M_16 = −∫ ν_y T dx = 0,   M_1(6+j) = −∫ ν_j ν_z T dx,   ν = Σ g_j ν_j,
// with T(x) [kg] the mass outboard of x per unit acceleration (`unit_axial_load`, e.g. ∫_x^L m dx'
// plus any point mass of the body). The boundary terms of eqs. 28–29 vanish in the convention of
// integrals.hpp: u(0) = 0, x = 0 at the root, and a tip mass is carried by T on [0, L] (integration
// by parts to L⁺) — which makes M_15 equal eq. 2's ∫ s_z dm exactly, tip mass included.
void apply_axial_inertia_correction(Eigen::MatrixXd& M, const SampledBody& body, const Eigen::VectorXd& g,
                                    const AxialForce& unit_axial_load);

}  // namespace fowtsim::flexbody
