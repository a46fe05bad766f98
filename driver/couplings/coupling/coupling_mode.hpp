#pragma once
// How the slow (rigid multibody, ΔT) and fast (flexible bodies, Δt = ΔT/n) subsystems exchange
// state (DESIGN.md §4).
#include <string>
#include <string_view>

namespace fowtsim::driver {

enum class CouplingMode {
  multi_rate,           // seed 000 §4.4.2: slow at ΔT with the loads averaged over the previous
                        // large step; fast sub-steps n times through the new slow motion
  predictor_corrector,  // as multi_rate, then the slow step is repeated once with the loads
                        // averaged over the current large step (one correction, no iteration)
  single_rate,          // conventional staggered loose coupling: one step size for both (n = 1)
};

struct CouplingSettings {
  CouplingMode mode = CouplingMode::multi_rate;
  double dt_coupling_s = 0.05;  // large step ΔT [s]
  int substeps = 10;            // n: small steps per large step, Δt = ΔT / n
  double t_max_s = 10.0;        // simulated time [s]

  double dt_s() const { return dt_coupling_s / substeps; }  // small step Δt [s]
  long large_steps() const;                                  // number of large steps to t_max_s
};

// Throws InputError naming the value when the text is not one of the modes.
CouplingMode parse_coupling_mode(std::string_view text);
std::string to_string(CouplingMode mode);

// Throws InputError on inconsistent settings (single_rate with n ≠ 1, ΔT ≤ 0, t_max not a
// multiple of ΔT within 1e-9 relative, …): every rate must divide the coupling step.
void validate(const CouplingSettings& settings);

}  // namespace fowtsim::driver
