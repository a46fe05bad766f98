#pragma once
// The YAML beam scene: one clamped beam (our own deck format for everything BeamDyn files do not
// cover), static or dynamic, with a rotating root, gravity and dead loads. Its keys are listed by
// `fowtsim --help-deck` and in inputs/beams/.
#include "fowtsim/io/schema.hpp"
#include "run/run_types.hpp"

namespace fowtsim::driver {

io::Schema beam_scene_schema();

RunReport run_beam_scene(const RunRequest& request, const ProgressCallback& progress);

// The YAML pipe scene: the beam scene's shape with a straight pipe conveying fluid (seed 000 Ch. 3,
// modules/beam/PIPE.md) instead of the beam: `pipe:` (tube, wall, ends, discretisation) and
// `fluid:` (density, flow, friction, end pressure). Shipped decks: inputs/pipes/.
io::Schema pipe_scene_schema();

RunReport run_pipe_scene(const RunRequest& request, const ProgressCallback& progress);

}  // namespace fowtsim::driver
