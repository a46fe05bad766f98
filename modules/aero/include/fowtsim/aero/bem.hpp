#pragma once
#include <limits>
// Steady blade-element momentum induction at one blade section, solved as one equation in the
// inflow angle φ with guaranteed bracketing (Ning 2014, "A simple solution method for the blade
// element momentum equations with guaranteed convergence", Wind Energy 17:1327–1345).
//
// Section kinematics in the node's blade frame b (params.hpp): V_x = relative wind along x_b
// (through the rotor plane, + downwind), V_y = relative wind along y_b (+ when the air meets the
// leading edge first, i.e. normal rotation). With axial and tangential induction a, a':
//   tan φ = V_x (1 − a) / (V_y (1 + a')),   α = φ − θ   (θ = twist + pitch),
//   c_n = C_l cos φ + C_d sin φ,   c_t = C_l sin φ − C_d cos φ,   σ' = B c / (2π r).
// Any sign of V_x, V_y is mapped onto the first quadrant by reflection (s_x = sign V_x,
// s_y = sign V_y: sin φ_c = s_x sin φ, cos φ_c = s_y cos φ, c_n,c = s_x c_n, c_t,c = s_y c_t), where
// Ning's residual is
//   R(φ_c) = sin φ_c / (1 − a(φ_c)) − (|V_x|/|V_y|) cos φ_c (1 − κ'(φ_c)),
//   κ = σ' c_n,c / (4 F sin²φ_c),  κ' = σ' c_t,c / (4 F sin φ_c cos φ_c),  a' = κ'/(1 − κ'),
//   a = κ/(1+κ)             for φ_c > 0, κ ≤ 2/3 (momentum region; sin φ_c/(1−a) = sin φ_c (1+κ)),
//   a = Buhl(κ, F)           for φ_c > 0, κ > 2/3 (empirical region, Ning eq. 18 / Buhl 2005),
//   a = κ/(κ−1)              for φ_c < 0 (propeller-brake region; sin φ_c/(1−a) = sin φ_c (1−κ)).
// Brackets are tried in Ning's order (0, π/2], [−π/4, 0), (π/2, π); if none changes sign the whole
// circle is scanned; if there is still no root the section gets zero induction and the status says
// so (never a silent failure, never NaN). Roots are polished by Brent's method; from a warm start
// (the previous root at the node) Newton–secant steps come first, the brackets being the fallback
// that always converges.
#include "fowtsim/aero/params.hpp"
#include "fowtsim/aero/polar.hpp"

namespace fowtsim::aero {

struct SectionInflow {
  double axial_velocity_m_s = 0.0;       // V_x: relative wind along x_b [m/s]
  double tangential_velocity_m_s = 0.0;  // V_y: relative wind along y_b [m/s]
  double local_radius_m = 0.0;           // r: distance of the node from the shaft axis [m] (> 0)
  double hub_radius_m = 0.0;             // R_hub: r of the blade's root node [m]
  double tip_radius_m = 0.0;             // R: r of the blade's tip node [m]
  double chord_m = 0.0;                  // c [m]
  double theta_rad = 0.0;                // θ = twist + pitch [rad]
  int number_of_blades = 3;              // B
};

enum class InductionStatus {
  converged,             // Newton–secant or Brent converged on a root of R(φ)
  zero_loss_factor,      // node at the hub or tip radius with that loss on: F = 0, momentum gives
                         // no finite induction; a = 1, a' = 0 (AeroDyn's published convention)
  no_axial_flow,         // |V_x| negligible: induction undefined, a = a' = 0
  no_tangential_flow,    // |V_y| negligible: φ = ±π/2, a from the axial balance, a' = 0
  still_air,             // V_x = V_y = 0: no loads
  no_root,               // R(φ) has no sign change on the circle: a = a' = 0 (counted in Output)
  beyond_momentum,       // a root with a < −1 or an induced velocity a V_x or a' V_y above twice the
                         // section's inflow speed: outside momentum theory (flow nearly in the blade's
                         // plane, e.g. a parked rotor yawed ~90°); a = a' = 0, as AeroDyn drops invalid roots
};

struct SectionSolution {
  double phi_rad = 0.0;              // inflow angle φ in (−π, π] [rad]
  double alpha_rad = 0.0;            // angle of attack α = φ − θ, wrapped to [−π, π) [rad]
  double axial_induction = 0.0;      // a [-]
  double tangential_induction = 0.0; // a' [-]
  double loss_factor = 1.0;          // F = F_tip F_hub at φ [-]
  double relative_speed_m_s = 0.0;   // W = |(V_x (1−a), V_y (1+a'))| [m/s]
  AirfoilCoefficients coefficients;  // C_l, C_d, C_m at α
  double cn = 0.0;                   // normal-force coefficient (along x_b, with drag) [-]
  double ct = 0.0;                   // tangential-force coefficient (along −y_b, with drag) [-]
  int residual_evaluations = 0;      // calls of R(φ) (cost diagnostic)
  double root_phi_c_rad = std::numeric_limits<double>::quiet_NaN();  // the root of R found (NaN: none);
                                     // the warm start of the next solve at this node
  double root_slope_per_rad = std::numeric_limits<double>::quiet_NaN();  // dR/dφ_c at the root, secant
                                     // estimate (NaN: found by bracketing); the next solve's first Newton step [1/rad]
  InductionStatus status = InductionStatus::converged;
};

// Solves the induction of one section. Allocates nothing; never returns non-finite numbers for
// finite input (throws NumericalError otherwise). A finite `warm_start` (a previous
// root_phi_c_rad at this node, with its root_slope_per_rad if known) is followed first by
// Newton–secant steps (typically 4 residual calls with the final one, against 7.8 for the bracket
// and Brent before; issue 28), confined to ±0.1 rad around it within its half circle (the solution
// continues the branch it was on, as a time-marching solver's would). If they leave that window
// or stall, the narrow bracket ±0.01 rad around the warm start is tried (Brent when R changes
// sign there), then the cold search of Ning's brackets. Every way converges to 1e-12 rad: the
// secant stops when its next step would be below Brent's tolerance 2ε|φ| + 0.5e-12.
// Roots between 0.01 and 0.1 rad from the warm start were, before issue 28, taken by the cold
// search; on the default deck (60 s, 9,700 of 153,204 solves, moves up to 0.047 rad) that search
// finds the same root to 6.4e-13 rad.
SectionSolution solve_section(const SectionInflow& inflow, const Polar& polar, const Params& params,
                              double warm_start = std::numeric_limits<double>::quiet_NaN(),
                              double warm_slope = std::numeric_limits<double>::quiet_NaN());

// The section quantities for given inductions (a, a'): φ, α, W, coefficients; the status and loss
// factor of `base` are kept. Used after the skewed-wake redistribution changes a.
SectionSolution section_with_induction(const SectionInflow& inflow, const Polar& polar,
                                       double axial_induction, double tangential_induction,
                                       const SectionSolution& base);

// Prandtl tip × hub loss factor at |sin φ| (Glauert 1935; hub form as in Moriarty & Hansen 2005,
// AeroDyn Theory Manual eqs. 4.1–4.2). Returns 0 at or beyond the tip (hub) radius when that
// loss is on.
double prandtl_loss_factor(const SectionInflow& inflow, double abs_sin_phi, bool tip_loss, bool hub_loss);

// Buhl's empirical axial induction for κ > 2/3 (Ning 2014 eq. 18): continuous with a = κ/(1+κ)
// at a = 0.4 for every F.
double buhl_axial_induction(double kappa, double loss_factor);

}  // namespace fowtsim::aero
