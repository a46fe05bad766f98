#pragma once
// Natural frequencies of the beam linearised about a base configuration: the eigenvalues of the
// assembled M q̈ + K q = 0 (seed 000 eq. 2.56 without damping) — for a beam at rest in a
// non-rotating frame, the classical free-vibration frequencies of the discretised beam.
#include <vector>

#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/beam_state.hpp"

namespace fowtsim::beam {

// The lowest `count` undamped natural frequencies [Hz], ascending, about `state` under `input`
// (frame rotation adds its inertial stiffness: centrifugal stiffening). Dense eigen-solve of
// M⁻¹K: O((6N)³), for analysis, not for the time loop.
std::vector<double> natural_frequencies_hz(const BeamModel& model, const BeamInput& input,
                                           const BeamState& state, int count);

}  // namespace fowtsim::beam
