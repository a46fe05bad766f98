#pragma once
// Time integration of a SpinningBeam under a prescribed HubSpin, from rest (q = q̇ = 0 at t = 0).
// Classical fourth-order Runge–Kutta (one of the two schemes the seed names in Sec. 2.3) with a
// fixed step, on the first-order form y = [q; q̇], ẏ = [q̇; q̈(q, Ω(t), α(t))]. Explicit: the step
// must resolve the highest rotating frequency (RK4 is stable for ω Δt < 2.78).
#include "fowtsim/flexbody/hub_spin.hpp"
#include "fowtsim/flexbody/spinning_beam.hpp"

#include <vector>

namespace fowtsim::flexbody {

// Tip deflection v(L) [m] at t = k·sample_s, k = 0 … round(end_s/sample_s), integrated with
// round(sample_s/max_step_s) rounded up equal steps per sample. Throws InputError unless
// end_s ≥ 0, sample_s > 0 and max_step_s > 0.
std::vector<double> spin_up_tip_history(const SpinningBeam& beam, const HubSpin& hub, double end_s,
                                        double sample_s, double max_step_s);

}  // namespace fowtsim::flexbody
