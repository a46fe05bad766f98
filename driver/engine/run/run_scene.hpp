#pragma once
// Reads a scene deck (validated in full before anything runs) and runs the scene it describes.
#include "run/run_types.hpp"

namespace fowtsim::driver {

RunReport run_scene(const RunRequest& request, const ProgressCallback& progress);

}  // namespace fowtsim::driver
