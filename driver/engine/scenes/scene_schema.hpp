#pragma once
// The schema of a scene deck: the sections every scene has (simulation, output) and the module
// sections a scene may list. A scene lists only what it uses (DESIGN.md §5).
#include "fowtsim/io/schema.hpp"

namespace fowtsim::driver {

io::Schema scene_schema();

}  // namespace fowtsim::driver
