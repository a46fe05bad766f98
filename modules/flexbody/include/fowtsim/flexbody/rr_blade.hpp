#pragma once
// The Rayleigh–Ritz blade body: generalised matrices of a blade with ElastoDyn's three shapes
// (blade_shapes.hpp), in the seed's thin-beam form (Sec. 2.2, 4.1–4.2), and ElastoDyn's own
// per-mode frequencies and damping. Blade axes at zero pitch: "flap" normal to the rotor plane
// (along the shaft), "edge" in the rotor plane; the rotor spins about the flap axis through the
// apex, HubRad inboard of the root. Precone and pitch are not included (a later multibody's
// kinematics carry them).
#include "fowtsim/flexbody/blade_shapes.hpp"

#include <Eigen/Dense>

namespace fowtsim::flexbody {

// About the blade root, x from the root (ElastoDyn's summary "Mass", "First Mass Moment",
// "Second Mass Moment").
struct BladeMassProperties {
  double mass = 0.0;           // ∫ m dx [kg]
  double first_moment = 0.0;   // ∫ m x dx [kg m]
  double second_moment = 0.0;  // ∫ m x² dx [kg m^2]
};
BladeMassProperties mass_properties(const SampledBlade& blade);

// Shapes in the order flap 1, flap 2, edge 1.
struct RrBladeMatrices {
  // Seed eq. 2's M_gg over the mean line: ∫ m (Φ_i · Φ_j) dx, both blade axes [kg].
  Eigen::Matrix3d mass;
  // Seed eq. 20 without torsion: ∫ (EI_flap κ_f,i κ_f,j + EI_edge κ_e,i κ_e,j) dx, κ along the
  // principal axes, then ×sqrt(t_i t_j) with t = (FlStTunr(1), FlStTunr(2), 1) as ElastoDyn tunes
  // its flap block [N/m]. Twisted shapes: diagonal in flap/edge (∫ EI_flap φ_i'' φ_j'' and
  // ∫ EI_edge φ''²); untwisted: ∫ (EI_flap cos²θ + EI_edge sin²θ) φ_i'' φ_j'' and a coupling.
  Eigen::Matrix3d stiffness;
  // Eq. 26 with the centrifugal axial force per unit Ω², T/Ω² = ∫_x^L m (HubRad + s) ds:
  // G = ∫ (T/Ω²) (Φ_i' · Φ_j') dx [kg = N/m per (rad/s)²].
  Eigen::Matrix3d centrifugal;
  // In-plane centrifugal softening per unit Ω²: ∫ m Φ_i,edge Φ_j,edge dx [kg] (the −Ω² M_q of
  // the in-plane spinning beam, spinning_beam.hpp, for the edge-axis component) [kg].
  Eigen::Matrix3d softening;
  // ElastoDyn's per-mode quantities, from the polynomial φ itself: ∫ m φ_i² (its MBF, MBE) and
  // ∫ (T/Ω²) φ_i'² (its KBFCent, KBECent per Ω²).
  Eigen::Vector3d mass_polynomial, centrifugal_polynomial;

  // K(Ω) = K + Ω² (G − S) [N/m]: stiffness of the blade on a hub spinning at Ω [rad/s].
  Eigen::Matrix3d stiffness_at(double omega) const { return stiffness + omega * omega * (centrifugal - softening); }
};
RrBladeMatrices rr_blade_matrices(const ElastoDynBlade& blade, const SampledBlade& sampled);

// Natural frequencies [Hz], ascending, of the 3×3 generalised eigenproblem K(Ω) v = ω² M v
// (coupled through M for twisted shapes, through K for untwisted ones).
Eigen::Vector3d natural_frequencies_hz(const RrBladeMatrices& m, double omega = 0.0);

// ElastoDyn's per-mode frequencies [Hz] (its FreqBF(i, ·), FreqBE(1, ·)): each shape alone, a
// Rayleigh quotient with the polynomial's mass, no tip mass:
//   f_i = sqrt((K_ii + Ω² ∫ (T/Ω²) φ_i'²) / ∫ m φ_i²) / 2π   (Ω = 0: FreqBF(i,1); Ω > 0: FreqBF(i,3)).
// Flap 1, flap 2, edge 1 (not sorted).
Eigen::Vector3d elastodyn_frequencies_hz(const RrBladeMatrices& m, double omega = 0.0);

// ElastoDyn's structural damping: ζ_l percent of critical for shape l, as a stiffness-proportional
// matrix C_il = (ζ_l/100) K_il / (π f_l), f_l = ElastoDyn's non-rotating per-mode frequency. For
// one shape alone this is c = 2 (ζ/100) ω m, critical damping scaled by ζ. (ElastoDyn scales the
// columns, so C is not symmetric when ζ/f differ between coupled shapes; kept as it does.)
Eigen::Matrix3d elastodyn_damping(const ElastoDynBlade& blade, const RrBladeMatrices& m);

}  // namespace fowtsim::flexbody
