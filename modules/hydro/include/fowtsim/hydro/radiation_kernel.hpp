#pragma once
// The radiation memory of potential-flow hydrodynamics (issue 15; Cummins 1962, Ogilvie 1964):
//   (M + A(∞)) ẍ + ∫_0^t K(t − τ) ẋ(τ) dτ + … = F,   K(t) = (2/π) ∫_0^∞ B(ω) cos(ωt) dω,
// and its inverse relation to the frequency-dependent added mass,
//   A(ω) = A(∞) − (1/ω) ∫_0^∞ K(t) sin(ωt) dt,
// which a table of A(ω), B(ω) (e.g. WAMIT's .1) must satisfy: the check that a kernel is right.
// B(ω) is taken piecewise linear between the tabulated frequencies, zero at ω = 0 when the table
// starts above it (a body radiates no waves at zero frequency) and zero beyond the last one; each
// piece is integrated against cos(ωt) in closed form (3-point Gauss where t·Δω < 0.1, whose error
// there is below 1e-9 of the piece), so long times need no finer frequency grid.
#include <span>
#include <vector>

#include "fowtsim/core/types.hpp"

namespace fowtsim::hydro {

// K at each of `times_s` [N/m, N, N·m per unit velocity and time]; frequencies ascending, ≥ 0.
std::vector<Mat6> retardation_kernel(std::span<const double> frequencies_rad_s, std::span<const Mat6> damping,
                                     std::span<const double> times_s);

// A(ω) from the kernel sampled at `times_s` (ascending, from 0; trapezoidal rule, the kernel taken
// as zero after the last time) and A(∞).
Mat6 added_mass_from_kernel(double omega_rad_s, std::span<const double> times_s, std::span<const Mat6> kernel,
                            const Mat6& added_mass_infinite_frequency);

}  // namespace fowtsim::hydro
