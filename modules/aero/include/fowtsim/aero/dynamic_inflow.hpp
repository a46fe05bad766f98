#pragma once
// Dynamic inflow: Øye's model as AeroDyn's DBEMT_Mod 2 (continuous) describes it (Snel & Schepers
// 1995, "Joint investigation of dynamic inflow effects and implementation of an engineering method",
// ECN-C--94-107; Branlard 2017, Wind Turbine Aerodynamics and Vorticity-Based Methods §10.2).
// Per node and per component (axial a V_x, tangential a' V_y), the quasi-steady induced velocity
// W_qs of the BEM solve passes two first-order filters:
//   τ1 dW_int/dt + W_int = W_qs + k τ1 dW_qs/dt,   τ2 dW/dt + W = W_int,   k = 0.6,
//   τ1 = 1.1/(1 − 1.3 min(ā, 0.5)) · R/Ū   (ā, Ū disk means of the axial induction and inflow),
//   τ2 = (0.39 − 0.26 (r/R)²) τ1.
// With z = W_int − k W_qs the derivative of the input disappears (a continuous state-space form
// without input derivatives, as a linearisation needs):
//   τ1 ż = (1 − k) W_qs − z,   τ2 Ẇ = z + k W_qs − W.
// z is continuous where W_qs jumps (W_int then jumps by k ΔW_qs: Øye's overshoot).
namespace fowtsim::aero {

inline constexpr double kOyeK = 0.6;

struct OyeFilter {
  double z = 0.0;  // W_int − k W_qs [m/s]
  double w = 0.0;  // filtered induced velocity W [m/s]
};

// τ1 of the disk [s]; the mean axial induction is capped at 0.5 as in Øye's formula.
double oye_tau1(double mean_axial_induction, double rotor_radius_m, double mean_inflow_m_s);
// τ2 of a node at r/R [s].
double oye_tau2(double tau1_s, double radius_ratio);

// The steady filter for W_qs held forever: z = (1 − k) W_qs, W = W_qs (exactly).
inline OyeFilter oye_steady(double w_qs) { return {(1.0 - kOyeK) * w_qs, w_qs}; }

// Exact solution over h with W_qs linear from u0 to u1 (first-order hold) and τ1, τ2 constant;
// τ2 < τ1 (τ2 ≤ 0.39 τ1 by the formula). With u0 = u1 and a steady start the result is the start
// bit for bit.
void advance_oye(OyeFilter& filter, double tau1_s, double tau2_s, double u0, double u1, double h);

}  // namespace fowtsim::aero
