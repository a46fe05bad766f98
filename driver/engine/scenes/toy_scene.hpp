#pragma once
// The verification scene: toy coupled oscillators through the multi-rate glue code, written
// with the exact solution alongside (default deck until the turbine modules land).
#include "fowtsim/io/schema.hpp"
#include "run/run_types.hpp"

namespace fowtsim::driver {

// Runs the scene described by a validated scene deck. Input errors throw InputError before the
// first step; numerical trouble throws NumericalError after the outputs are closed with every
// step so far and a "failed: …" status.
RunReport run_toy_scene(const io::ValidatedDeck& deck, const RunRequest& request, const ProgressCallback& progress);

}  // namespace fowtsim::driver
