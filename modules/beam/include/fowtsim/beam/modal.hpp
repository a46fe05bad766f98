#pragma once
// Natural frequencies of the beam linearised about a base configuration: the eigenvalues of the
// assembled M q̈ + K q = 0 (seed 000 eq. 2.56 without damping) — for a beam at rest in a
// non-rotating frame, the classical free-vibration frequencies of the discretised beam.
#include <complex>
#include <vector>

#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/beam_state.hpp"

namespace fowtsim::beam {

// The lowest `count` undamped natural frequencies [Hz], ascending, about `state` under `input`
// (frame rotation adds its inertial stiffness: centrifugal stiffening). Dense eigen-solve of
// M⁻¹K: O((6N)³), for analysis, not for the time loop.
std::vector<double> natural_frequencies_hz(const BeamModel& model, const BeamInput& input,
                                           const BeamState& state, int count);

// A mode of the whole locally linear system M q̈ + C q̇ + K q = 0 (eq. 2.56; for a pipe, the flow's
// gyroscopic and follower terms make C and K non-symmetric): q = Re(x e^{λt}).
struct DampedMode {
  std::complex<double> eigenvalue;  // λ = σ + iω_d: σ < 0 decays, σ > 0 grows [1/s]
  Vec6 share = Vec6::Zero();        // Σ_n |x_k|² over nodes for k = u_x, u_y, u_z (sharing 1) and
                                    // θ_x, θ_y, θ_z (sharing 1), components in f [-]: which way it moves
  Eigen::VectorXcd shape;           // x: [u*; θ*] of every node in f (6N), unit norm, any phase [m, rad]
};

// The modes with Im λ > 0 (one of each complex pair) and the non-oscillating ones (Im λ = 0),
// ascending by |λ|. Dense eigen-solve of the 12N first-order system: for analysis.
std::vector<DampedMode> damped_modes(const BeamModel& model, const BeamInput& input, const BeamState& state);

}  // namespace fowtsim::beam
