#pragma once
// A whole time-domain record at once, for the module's tests and any caller that holds the wave
// history: the stepping module of time_stepping.hpp (RK4, nonlinear Morison drag, mode-acceleration
// recovery; seed 004 "Solution in Time Domain") run from rest over a WaveHistory, every output kept.
// The engine steps the module itself instead (driver/engine/scenes/slender_time_domain.hpp).
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
