#pragma once
// Unsteady airfoil aerodynamics of one blade section: the four-state dynamic-stall model of
// Hansen, Gaunaa & Madsen (2004), "A Beddoes–Leishman type dynamic stall model in state-space and
// indicial formulations", Risø-R-1354(EN) ("HGM"; AeroDyn UA_Mod 4), incompressible.
//
// Inputs at a time: angle of attack α at the aerodynamic centre (the node, ¼ chord), relative speed
// W, the section's rotation rate ω about its span axis z_a (+ raises α) and the chord c.
//   T_u = c/(2W)                                  (time for the flow to pass half a chord)
//   α34 = atan2(W sin α + ω c/2, W cos α)          (¾-chord angle: ω moves the ¾-chord point)
// States (HGM eqs. 3.9–3.13; Jones' two-pole approximation of Wagner's function for the shed wake,
// A1 = 0.165, b1 = 0.0455, A2 = 0.335, b2 = 0.3):
//   ẋ1 = −(b1/T_u) x1 + (b1 A1/T_u) α34,   ẋ2 = −(b2/T_u) x2 + (b2 A2/T_u) α34
//   α_E = α34 (1 − A1 − A2) + x1 + x2                       (effective angle of attack)
//   C_L^p = C_l,α (α_E − α0) + π T_u ω                       (attached lift incl. added mass)
//   ẋ3 = (C_L^p − x3)/(τ_p T_u)                              (leading-edge pressure lag)
//   α_F = x3/C_l,α + α0,   ẋ4 = (f_st(α_F) − x4)/(τ_f T_u)   (boundary-layer lag of separation)
// Outputs (HGM eqs. 3.14–3.16 as documented for AeroDyn UA_Mod 4):
//   C_l = x4 C_l,α (α_E − α0) + (1 − x4) C_l,fs(α_E) + π T_u ω
//   C_d = C_d(α_E) + (α − α_E) C_l + (C_d(α_E) − C_d(α0)) [(√f_st(α_E) − √x4)/2 − (f_st(α_E) − x4)/4]
//   C_m = C_m(α_E) − (π/2) T_u ω
// with the static separation function of a Kirchhoff flat plate and the fully separated lift
//   f_st(α) = (2 √(C_l^st(α)/(C_l,α (α − α0))) − 1)²,   C_l,fs = (C_l^st − C_l,α (α − α0) f_st)/(1 − f_st),
// f_st = 0 beyond its first zero on either side of α0 (then C_l,fs = C_l^st). f_st is not clipped
// at 1 where the polar is locally steeper than C_l,α (slightly, near α0), so the identity
// C_l^st = f_st C_l,α(α−α0) + (1 − f_st) C_l,fs holds everywhere.
// In steady flow (ω = 0) every state sits at its input and the outputs are the static polar exactly.
// τ_p = 1.5, τ_f = 6.0 are HGM's (Risø-R-1354 §4; AeroDyn's defaults T_p0 = 1.7, T_f0 = 3 may be
// set instead). Beyond |α| = cutout the static polar is used (blended over the 5° below it, as
// AeroDyn's UACutout) and the states follow their steady values at the cutout.
#include "fowtsim/aero/polar.hpp"

namespace fowtsim::aero {

struct StaticSeparation {
  double f = 1.0;       // f_st(α) [-]
  double cl_fs = 0.0;   // C_l,fs(α) [-]
};
// f_st and C_l,fs at α (C_l^st(α) = cl_static). Written as C_l,fs = C_l,α (α−α0)(1 + 3√f)/(4(1 + √f)),
// the same value as the definition but regular at f_st = 1 (where it gives C_l,α(α−α0)/2).
StaticSeparation static_separation(const SeparationData& s, double alpha_rad, double cl_static);

struct UnsteadyAirfoilConstants {
  double pressure_time_constant = 1.5;    // τ_p, in units of T_u (HGM)
  double separation_time_constant = 6.0;  // τ_f, in units of T_u (HGM)
  double cutout_rad = 0.7853981633974483; // |α| beyond which the static polar is used (45°)
};

struct SectionMotion {
  double alpha_rad = 0.0;          // α at the aerodynamic centre [rad]
  double speed_m_s = 0.0;          // W [m/s]
  double pitch_rate_rad_s = 0.0;   // ω about z_a [rad/s]
  double chord_m = 1.0;            // c [m]
};

// The four states and the inputs at the state's time (the start of the next step's first-order hold).
struct UnsteadyAirfoilState {
  double x1 = 0.0, x2 = 0.0;       // shed-wake states [rad]
  double x3 = 0.0;                 // lagged attached lift C_L^p [-]
  double x4 = 1.0;                 // separation point f [-], ≥ 0 (≈ 1 attached)
  double alpha34_rad = 0.0, time_unit_s = 0.0, pitch_rate_rad_s = 0.0;
};

// The steady state for a motion held forever (outputs = static polar at α when ω = 0).
UnsteadyAirfoilState unsteady_airfoil_steady(const Polar& polar, const SeparationData& sep,
                                             const UnsteadyAirfoilConstants& k, const SectionMotion& m);

// Advances the states over dt to the motion `end`: exact solution of each linear state equation
// with its input linear in time between the stored start values and `end` (first-order hold;
// T_u at the mean of the two ends), x1, x2, then x3, then x4 — unconditionally stable, second
// order. Allocates nothing.
void advance_unsteady_airfoil(const Polar& polar, const SeparationData& sep, const UnsteadyAirfoilConstants& k,
                              const SectionMotion& end, double dt, UnsteadyAirfoilState& state);

// Dynamic C_l, C_d, C_m for the motion now, with the states (α34 feeds through). Static polar for
// a non-lifting section or beyond the cutout.
AirfoilCoefficients unsteady_coefficients(const Polar& polar, const SeparationData& sep,
                                          const UnsteadyAirfoilConstants& k, const SectionMotion& now,
                                          const UnsteadyAirfoilState& state);

// Jones' constants (HGM Table 1).
inline constexpr double kJonesA1 = 0.165, kJonesB1 = 0.0455, kJonesA2 = 0.335, kJonesB2 = 0.3;

// x(h) of ẋ = λ (g u(t) − x), u linear from u0 to u1 over h, x(0) = x0 (exact; λ ≥ 0).
double first_order_hold(double x0, double lambda, double gain, double u0, double u1, double h);

}  // namespace fowtsim::aero
