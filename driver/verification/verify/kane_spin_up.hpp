#pragma once
// Kane's spin-up beam (seed 002 Sec. 5.2) across two modules: the Rayleigh–Ritz equations of
// modules/flexbody (spinning_beam.hpp, eq. 32 modes, geometric stiffening of eq. 26) against the
// MBBT finite-volume beam of modules/beam, both spun up by the same prescribed hub motion. Shared
// by driver/tests/kane_spin_up_tests.cpp and `fowtsim verify flexbody`.
#include <functional>
#include <vector>

#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/beam_state.hpp"
#include "fowtsim/flexbody/hub_spin.hpp"

namespace fowtsim::driver {

// An MBBT beam clamped at the origin of a frame spinning about z with the hub's Ω(t), α(t), from
// rest at Δt = 5 ms (generalized-α at the input time of each step): observe(state) at t = 0 and
// every sample_s up to end_s. The time loop of Kane's spin-up, straight and pre-bent.
void mbbt_spin_up(const beam::BeamModel& model, const flexbody::HubSpin& hub, double end_s, double sample_s,
                  const std::function<void(const beam::BeamState&)>& observe);

// In-plane tip deflection [m] on a common grid (every 20 ms over 0–20 s: 15 s spin-up, 5 s at
// Ω_s = 6 rad/s). MBBT: modules/beam's Kane beam, 30 segments, Δt = 5 ms, clamped at the origin of a
// floating frame rotating about z with Ω(t), α(t) (its converged setting). RR: flexbody with n eq. 32
// modes (M_t = 0), RK4 at 1 ms. modules/beam's own RR reference (kane_rayleigh_ritz_tip, Simpson
// quadrature, its own β_j and hub profile) with 3 modes.
struct KaneSpinUp {
  std::vector<double> mbbt, rr1, rr3, beam_rr3;
};
KaneSpinUp kane_spin_up_histories();

double max_abs(const std::vector<double>& v);
// RMS of a − b over the grid, divided by max |b|.
double rms_over_max(const std::vector<double>& a, const std::vector<double>& b);
// max |a − b| over the grid.
double max_abs_difference(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace fowtsim::driver
