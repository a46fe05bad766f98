#pragma once
// Frequency-domain solution (seed 004, slides "Solution in Frequency Domain", solve4frf.m):
// a = [−ω²I + iωC_b + Ω²]⁻¹ Q_b with the damping matrix C_b = Ψᵀ C Ψ kept full (structural damping
// plus the linearised drag is not diagonal in the modes), then the generalised response by mode
// acceleration, q = K⁻¹[Q − MΨ(−ω²a) − CΨ(iωa)], so that a few modes suffice (the quasi-static
// part of every mode is kept). Morison drag ½ρCdD|u_r|u_r is linearised as ½ρCdD γ u_r per strip
// and γ iterated with the response until it converges (slide "Solution in Frequency Domain" 2).
#include "fowtsim/slender/modes.hpp"
#include "fowtsim/slender/wave_kinematics.hpp"

namespace fowtsim::slender {

enum class Recovery {
  ModeDisplacement,  // q = Ψ a
  ModeAcceleration,  // q = K⁻¹[Q − MΨä − CΨȧ] (needs K positive definite)
};

struct FrequencyDomainOptions {
  Recovery recovery = Recovery::ModeAcceleration;
  double tolerance = 1e-10;  // convergence of γ: max |Δγ| <= tolerance · max γ [-]
  int max_iterations = 500;  // of the drag-linearisation loop; NumericalError beyond
};

// One linear solve: q (n) for forcing f (N, complex force per length [N/m]) and linear drag
// damping c (N, force per length per relative velocity [N·s/m²]) at frequency ω.
VecXc solve_generalised(const Model& model, const Modes& modes, double omega_rad_s, const VecXc& force_N_m,
                        const VecX& drag_damping_N_s_m2, Recovery recovery);

struct HarmonicResponse {
  double omega_rad_s;            // ω
  double wave_amplitude_m;       // a
  VecXc q;                       // generalised response: q(t) = Re(q e^{iωt}) (n)
  VecXc relative_velocity_m_s;   // u_r = aU − iωv per strip (N)
  VecXc excitation_N_m;          // a(ρCmA iωU + cU): the wave force on the body at rest (N)
  VecX drag_damping_N_s_m2;      // c = ½ρCdD f (8/3π)|u_r| per strip (N)
  int iterations;                // of the drag linearisation
};

// Regular wave of amplitude a: γ = (8/3π)|u_r| (the equivalent linearisation that matches the
// drag's work per cycle). velocity_transfer: U per strip (N), e.g. from velocity_transfer().
HarmonicResponse solve_harmonic(const Model& model, const Modes& modes, double omega_rad_s, double wave_amplitude_m,
                                const VecXc& velocity_transfer, const FrequencyDomainOptions& options = {});

// Load per length on each strip for the inertia-relief moment (N) [N/m]: the wave force with the
// linearised drag on the relative velocity, minus the inertia (structural + added mass) and the
// mass-proportional damping, p = a(ρCmA iωU) + c u_r + ω² m v − iω α m v.
VecXc harmonic_load_per_length(const Model& model, const HarmonicResponse& response);
// r = q̈ + α q̇ = (−ω² + iωα) q: the generalised inertia of the point masses' d'Alembert forces (n).
VecXc harmonic_inertial_q(const Model& model, const HarmonicResponse& response);

struct RandomResponse {
  VecX omega_rad_s;              // ω_j (Nf), equally spaced by delta_omega
  double delta_omega_rad_s;      // Δω
  VecX wave_spectrum_m2_s;       // S_η(ω_j) [m²·s/rad] (Nf)
  MatXc q_transfer;              // q per unit wave amplitude at each ω_j (n × Nf) [-/m]
  MatXc relative_velocity_transfer; // u_r per unit amplitude (N × Nf) [1/s]
  VecX sigma_relative_velocity_m_s; // σ_{u_r} per strip (N)
  VecX drag_damping_N_s_m2;      // c = ½ρCdD f √(8/π) σ_{u_r} (N)
  int iterations;
};

// Irregular sea S_η(ω): γ = √(8/π) σ_{u_r}, σ² = Σ_j S_η(ω_j)|u_r(ω_j)|² Δω (the Gaussian
// statistical linearisation; the seed's printed "Σ√(2S)dω" is garbled — the variance of u_r is the
// integral of its spectrum). velocity_table: U (N × Nf) on the same ω_j.
RandomResponse solve_random(const Model& model, const Modes& modes, const VecX& omegas_rad_s,
                            const VecX& wave_spectrum_m2_s, double delta_omega_rad_s, const MatXc& velocity_table,
                            const FrequencyDomainOptions& options = {});

struct RmsProfiles {
  VecX displacement_m;     // σ_v per strip (N)
  VecX bending_moment_N_m; // σ of EI v'' (N)
  VecX stress_Pa;          // σ of the bending stress EI v''/Z at the outer fibre (N)
  VecX inertia_relief_moment_N_m; // σ of the inertia-relief moment (N): the only one of a rigid body
  VecX inertia_relief_stress_Pa;  // σ of its stress M_IR/Z (N)
};

// σ² = Σ_j S_η(ω_j)|H(ω_j)|² Δω for each response H (slide "Frequency Domain Analysis & Random Wave").
// The inertia-relief moment's H(ω_j) is inertia_relief_moment on the load per unit wave amplitude
// (harmonic_load_per_length of the response at ω_j with the converged linear drag).
RmsProfiles rms_profiles(const Model& model, const RandomResponse& response);
// The same with the inertia-relief moment's spectrum already at hand (inertia_relief_spectrum).
RmsProfiles rms_profiles(const Model& model, const RandomResponse& response, const MatX& inertia_relief_spectrum);

// Response spectrum of the displacement, S_v(x_i, ω_j) = |V_i(ω_j)|² S_η(ω_j) (N × Nf) [m²·s/rad].
MatX displacement_spectrum(const Model& model, const RandomResponse& response);
// Response spectrum of the inertia-relief moment, |M_IR(x_i, ω_j)|² S_η(ω_j) (N × Nf) [N²·m²·s/rad].
MatX inertia_relief_spectrum(const Model& model, const RandomResponse& response);

}  // namespace fowtsim::slender
