#pragma once
// Kane's spin-up beam pre-bent along the rotation axis (the seed's Sec. 5.4): one Rayleigh–Ritz
// body with edge (in the rotation plane, y), flap (along the axis z, about the pre-bent line) and
// torsion (about the mean line) shape functions, clamped on the axis of a hub spinning about z
// with a prescribed Ω(t), α(t). Derived here from the seed's Sec. 2–4 for this case.
//
// Geometry (Sec. 4.1). Mean line s_P0 = u⁰ = [x, 0, z₀(x)], z₀ = z_L (1 − cos(πx/2L)), z_L = −0.5 m;
// c = z₀'' its curvature. Deflection u_y = Σ g_e ψ_e (edge), u_z = Σ g_f ψ_f (flap), twist
// φ = ν_x^g = Σ g_t ν_t (Sec. 4.3), ψ the eq. 32 modes, ν the Sec. 5.3 sines. Thin beam, u_x = x;
// |z₀'| ≤ 0.079 so arclength = x to 0.3 % (dropped). COG on the mean line (ρ⁰ = 0), so eq. 30's
// Φ̃ = Φ: torsion moves no mass point of the line.
//
// Kinetic energy (eqs. 2, 18, 31). ω = Ω e_z, ω̇ = α e_z, hub origin fixed. The line points give
// the straight-beam terms of spinning_beam.hpp for edge (−α ∫ m x ψ_e, softening −Ω² M_ee,
// centrifugal T = Ω² ∫_x^L m s ds) and nothing for flap (no acceleration along the axis). Note the
// ∫ m z₀ … blocks of eq. 2 couple g with the body's rotations about x and y; the hub turns about z
// only and (s₀ × Φ)·e_z = x ψ_e for every shape, so z₀ adds no inertial coupling through them. It
// enters through eq. 31's j_G, the section's polar inertia about the tangent t ≈ [1, u_y', z₀'+u_z']:
// ½ j_G (φ̇ + Ω t·e_z)² = ½ j_G (φ̇ + Ω (z₀' + u_z'))², whose Lagrange terms are kept in full:
//   torsion  + j_G φ̈ + j_G Ω u̇_z' + j_G α (z₀' + u_z'),   flap  − j_G Ω φ̇ ψ' − j_G Ω² (z₀' + u_z') ψ'.
// Axial load (Sec. 4.2, eq. 26). The centrifugal T acts on the total slope ν = ν⁰ + ν^g (Sec. 4.1):
// the work of T on the shortening ½∫(z₀' + u_z')² gives K^T = Ω² G on u_z' and the pre-bend force
// −Ω² ∫ T̂ z₀' ψ_f' (T̂ = T/Ω²): what straightens the beam. Its Coriolis part (2Ω × the radial
// velocity −∫₀^x z₀' u̇_z' of the straightening) is dropped with u_x = x as in the seed (measured
// order: ~2 mm/s radial speed, 2Ωẋ ≈ 0.03 m/s² against α x ≈ 8 m/s², 0.3 %).
// Strain energy (eq. 20 in the section frame R_s⁰B of the curved line, linearised):
//   κ_x = φ' − c u_y',   κ_edge = u_y'' + c φ,   κ_flap = u_z''   (k = k⁰ + δθ' + k⁰ × δθ)
//   V = ½ ∫ [GK_t κ_x² + EI κ_edge² + EI κ_flap²] dx.
// The c φ term is the seed's Sec. 4.3 "non-linear correction" p_x^M = −κ M with κ = κ⁰ and M the
// edge bending moment, written as energy: the edge bending moment of the spin-up twists the
// pre-bent line — the torsion the seed reports. Both bending stiffnesses are EI (Sec. 5.2).
// Altogether, q = [g_e; g_f; g_t]:
//   M q̈ + Ω D q̇ + [K + Ω² (G − S) + α A] q = −α b + Ω² p,
//   M = diag(∫ m ψψ, ∫ m ψψ, ∫ j_G νν);  K_ee = ∫ EI ψ''ψ'' + GK c² ψ'ψ', K_et = ∫ EI c ψ''ν − GK c ψ'ν',
//   K_tt = ∫ GK ν'ν' + EI c² νν, K_ff = ∫ EI ψ''ψ'';  G_ee, G_ff = ∫ T̂ ψ'ψ';  S_ee = M_ee,
//   S_ff = ∫ j_G ψ'ψ';  D_tf = −D_ftᵀ = ∫ j_G ν ψ';  A_tf = ∫ j_G ν ψ';  b_e = ∫ m x ψ, b_t = ∫ j_G z₀' ν;
//   p_f = −∫ (T̂ − j_G) z₀' ψ'.
// Not modelled: axial stretch (EA), rotary inertia of the sections about the bending axes (EB),
// O(q²) terms (Sec. 4.2's Coriolis/α parts of T, the twist's rotation of the bending axes).
#include "fowtsim/flexbody/hub_spin.hpp"
#include "fowtsim/flexbody/quadrature.hpp"

#include <Eigen/Dense>
#include <vector>

namespace fowtsim::flexbody {

struct PrebentBeam {
  double length = 10.0;                // L [m]
  double mass_per_length = 1.2;        // m [kg/m]
  double bending_stiffness = 14.0e3;   // EI, edge and flap [N m²]
  double polar_inertia = 2.0;          // j_G [kg m]
  double torsion_stiffness = 200.0;    // GK_t [N m²]
  double prebend_tip = -0.5;           // z_L: z₀ = z_L (1 − cos(πx/2L)) [m]
};

class PrebentSpinningBeam {
 public:
  // n_edge, n_flap eq. 32 modes (M_t = 0), n_torsion Sec. 5.3 sines; each ≥ 1 (InputError).
  PrebentSpinningBeam(const PrebentBeam& beam, int n_edge, int n_flap, int n_torsion,
                      const QuadratureRule& rule = {});

  // q̈ at hub speed Ω and acceleration α.
  Eigen::VectorXd acceleration(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot, double rate,
                               double angular_acceleration) const;

  int size() const { return static_cast<int>(mass_.rows()); }
  double edge_tip(const Eigen::VectorXd& q) const { return edge_tip_.dot(q); }                   // u_y(L) [m]
  double flap_tip(const Eigen::VectorXd& q) const { return prebend_tip_ + flap_tip_.dot(q); }    // z₀(L) + u_z(L) [m]
  double torsion_tip(const Eigen::VectorXd& q) const { return torsion_tip_.dot(q); }             // φ(L) [rad]

 private:
  Eigen::MatrixXd mass_, stiffness_, centrifugal_, softening_, gyroscopic_, alpha_coupling_;
  Eigen::VectorXd euler_load_, prebend_load_, edge_tip_, flap_tip_, torsion_tip_;
  double prebend_tip_;
  Eigen::LLT<Eigen::MatrixXd> mass_llt_;
};

// Tip histories at t = k·sample_s, k = 0 … round(end_s/sample_s), from rest in the pre-bent shape
// (q = q̇ = 0), classical RK4 with ceil(sample_s/max_step_s) equal steps per sample.
struct PrebentTipHistory {
  std::vector<double> edge, flap, torsion;  // u_y(L) [m], z(L) [m], φ(L) [rad]
};
PrebentTipHistory prebent_spin_up_history(const PrebentSpinningBeam& beam, const HubSpin& hub, double end_s,
                                          double sample_s, double max_step_s);

}  // namespace fowtsim::flexbody
