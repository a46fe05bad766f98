#pragma once
// The verification scene: toy coupled oscillators through the multi-rate exchange, written with
// the exact solution alongside.
#include "fowtsim/io/schema.hpp"
#include "run/run_types.hpp"

namespace fowtsim::driver {

io::Schema toy_scene_schema();  // simulation, output, toy_oscillators

// Runs the scene described by a validated scene deck. Input errors throw InputError before the
// first step; numerical trouble throws NumericalError after the outputs are closed with every
// step so far and a "failed: …" status.
RunReport run_toy_scene(const io::ValidatedDeck& deck, const RunRequest& request, const ProgressCallback& progress);

}  // namespace fowtsim::driver
