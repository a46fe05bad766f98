#pragma once
// The platform-loads scene: a platform moved along a prescribed trajectory (fixed offset plus
// harmonic motions per DOF) through a sea, with its hydrodynamic and hydrostatic loads and its
// mooring — what OpenFAST's HydroDyn and MAP++ drivers do, so a hydro or mooring model can be run
// and compared on its own. Any of `waves:`, `hydro:`, `mooring:` may be left out (skip what the
// scene does not need).
#include "fowtsim/io/schema.hpp"
#include "run/run_types.hpp"

namespace fowtsim::driver {

io::Schema platform_scene_schema();
RunReport run_platform_scene(const RunRequest& request, const ProgressCallback& progress);

}  // namespace fowtsim::driver
