#pragma once
// Time-domain solution (seed 004, slides "Solution in Time Domain", solve4XXXTIMEResponse.m and
// mode_acc.m): the modal first-order system ż = [ȧ; Q_b − C_b ȧ − Ω² a], z = [a; ȧ] (the slide's
// ż = B − Az), with C_b from structural damping only and the full nonlinear Morison force on the
// relative velocity at each strip in Q_b (slide "Wave Force - Morison's Equation"):
//   f = ρ Cm A u̇ + ½ρ Cd D |u − v̇|(u − v̇)   (the −ρCaA v̈ part is the added mass in M).
// Fixed-step RK4 (the seed used ode45); the response is recovered by mode acceleration,
// q = K⁻¹[Q − MΨä − CΨȧ] with ä = Q_b − C_b ȧ − Ω²a re-evaluated at the output time.
#include "fowtsim/slender/frequency_domain.hpp"
#include "fowtsim/slender/wave_synthesis.hpp"

namespace fowtsim::slender {

struct TimeDomainOptions {
  double time_step_s;        // Δt; the wave history must be sampled at Δt/2 (RK4 midpoints)
  int steps;                 // number of steps; the run covers [0, steps·Δt]
  int output_every = 1;      // keep every k-th step (and t = 0)
  Recovery recovery = Recovery::ModeAcceleration;
};

struct TimeDomainResult {
  VecX time_s;               // output times (outputs)
  MatX q;                    // generalised coordinates (n × outputs)
  MatX displacement_m;       // v at the strip midpoints (N × outputs)
  MatX moment_elastic_N_m;   // EI v'' (N × outputs)
  MatX moment_inertia_relief_N_m; // inertia-relief moment (N × outputs)
};

// Starts from rest (a = ȧ = 0). Throws NumericalError with the time when the state turns non-finite.
TimeDomainResult simulate(const Model& model, const Modes& modes, const WaveHistory& waves,
                          const TimeDomainOptions& options);

}  // namespace fowtsim::slender
