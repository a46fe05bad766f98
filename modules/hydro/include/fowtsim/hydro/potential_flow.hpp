#pragma once
// Radiation of a rigid platform from frequency-domain potential-flow coefficients (issue 15;
// Cummins 1962): with q̇ = [ṙ_ref; ω] in the inertial frame,
//   (M + A(∞)) q̈ = … + F_rad + F_exc,   F_rad(t) = −∫_0^T K(τ) q̇(t − τ) dτ,
//   K(t) = (2/π) ∫_0^∞ B(ω) cos(ωt) dω   (radiation_kernel.hpp).
// A(∞) goes to the solver's mass matrix (Hydro::Output::added_mass), never into a load. The memory
// integral is evaluated by one of
//   convolution:  the trapezoidal rule on the history of q̇ sampled at the large step ΔT over the
//                 window T (HydroDyn RdtnMod 1, RdtnTMax); the kernel is tabulated at ΔT/2, so a
//                 Runge–Kutta stage at t_n, t_n + ΔT/2 or t_n + ΔT reads exact kernel samples, and
//                 the newest interval [t_n, t] takes the stage's own velocity (trapezoid);
//   state_space:  every kernel entry fitted as Σ_m Re(w_m r_m e^{p_m t}) (kernel_realization.hpp);
//                 per term a complex state ξ̇ = p ξ + q̇_j with F_i = −Σ Re(w r ξ), advanced over a
//                 step exactly for a velocity linear in time between t_n and the stage (first-order
//                 hold): ξ(t_n + h) = e^{ph} ξ_n + h[(φ₁ − φ₂)(ph) q̇_n + φ₂(ph) q̇(t_n + h)],
//                 φ₁(z) = (e^z − 1)/z, φ₂(z) = (e^z − 1 − z)/z².
// Both are explicit in the memory and implicit in nothing: the force at a stage is a function of the
// stored state and the stage velocity, so the platform's step stays the only step. The memory
// starts from rest (q̇ = 0 before t = 0).
#include <array>
#include <complex>
#include <span>
#include <vector>

#include "fowtsim/core/types.hpp"
#include "fowtsim/hydro/kernel_realization.hpp"

namespace fowtsim::hydro {

enum class RadiationMethod { convolution, state_space };

// Frequency-domain radiation coefficients about the platform reference point, inertial axes, DOF
// order surge, sway, heave, roll, pitch, yaw (io::WamitRadiation made dimensional).
struct RadiationTable {
  std::vector<double> frequencies_rad_s;  // ascending, > 0
  std::vector<Mat6> damping;              // B(ω) [N·s/m, N·s, N·m·s]
  Mat6 added_mass_infinite_frequency = Mat6::Zero();  // A(∞) [kg, kg·m, kg·m²]
};

struct RadiationOptions {
  RadiationMethod method = RadiationMethod::convolution;
  double window_s = 60.0;      // T: memory kept (HydroDyn RdtnTMax) [s] (> 0)
  double step_s = 0.0;         // ΔT: the platform's step, the only step advance() takes [s] (> 0)
  double fit_tolerance = 0.002; // state_space: relative error allowed per kernel entry [-]
  int fit_max_order = 20;      // state_space: largest realisation order per entry [-]
};

// One kernel entry K_ij that is not negligible (README "Potential flow": which are kept).
struct RadiationEntry {
  int row = 0, col = 0;         // i (load), j (velocity)
  ExponentialFit fit;           // state_space
  int first_term = 0;           // state_space: its first state in RadiationState::modal
  double tail_ratio = 0.0;      // |K_ij| over the last second of the window / its peak: how much
                                //   memory the window cuts off (HydroDyn: "make sure RdtnTMax is
                                //   long enough for the kernels to decay")
};

struct RadiationModel {
  RadiationMethod method = RadiationMethod::convolution;
  double step_s = 0.0;          // ΔT [s]
  int window_steps = 0;         // N = ⌈T/ΔT⌉
  Mat6 added_mass_infinite_frequency = Mat6::Zero();
  std::vector<RadiationEntry> entries;
  // convolution: K_e(k ΔT/2) of entry e at kernel[k · entries.size() + e], k = 0 … 2N + 2 (all
  // entries of one time side by side: one pass over the history serves them all)
  std::vector<double> kernel;
  int term_count = 0;           // state_space: complex states
  double fit_tolerance = 0.0;   // state_space: the tolerance asked for (a fit may miss it: see fit)
};

// The radiation memory at t_n: copyable, checkpointed through its field list.
struct RadiationState {
  double time_s = 0.0;                        // t_n [s]
  Vec6 velocity = Vec6::Zero();               // q̇(t_n)
  std::vector<Vec6> history;                  // convolution: q̇(t_n − k ΔT) at index (newest − k) mod (N + 1)
  int newest = 0;
  std::vector<std::complex<double>> modal;    // state_space: ξ_m(t_n)
  // convolution: the history part of the integral (all but the newest interval) at the stage
  // times t_n, t_n + ΔT/2, t_n + ΔT, summed once per step instead of at every stage.
  std::array<Vec6, 3> history_load{Vec6::Zero(), Vec6::Zero(), Vec6::Zero()};
};

// Its field list (core/fields.hpp).
template <class Archive>
void fields(Archive& a, RadiationState& s) {
  a.io(s.time_s, s.velocity, s.history, s.newest, s.modal, s.history_load);
}

// Kernel, and for state_space its fit, from the table. Throws InputError for bad options or a
// table that is not ascending.
RadiationModel make_radiation_model(const RadiationTable& table, const RadiationOptions& options);

// At rest before t0, velocity q̇0 at t0.
RadiationState make_radiation_state(const RadiationModel& model, double t0_s, const Vec6& velocity);

// F_rad at time t ∈ [t_n, t_n + ΔT] for the velocity q̇(t) [N, N·m], about the reference point, g.
// Allocates nothing. Throws std::logic_error for t outside the step.
Vec6 radiation_load(const RadiationModel& model, const RadiationState& state, double t_s, const Vec6& velocity);

// Moves the memory to t_n + ΔT, where the velocity is `velocity`. Allocates nothing.
void advance_radiation(const RadiationModel& model, double t_end_s, const Vec6& velocity, RadiationState& state);

}  // namespace fowtsim::hydro
