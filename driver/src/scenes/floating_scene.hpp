#pragma once
// The floating-turbine scene: the rigid multibody (platform + tower, nacelle, rotor with rigid
// blades, drivetrain) under gravity, hydrodynamics, hydrostatics and mooring, in a sea. Hydro and
// mooring are evaluated at every Runge–Kutta stage of the large step (their loads depend on the
// pose), the hydro added mass goes to the left-hand side. Parked or free-spinning rotor without
// aerodynamics (aero and the controller join with issue 4/6 follow-ups). The OC3-Hywind free-decay
// decks (inputs/oc3_hywind/free_decay_*.yaml) are its verification cases.
#include "fowtsim/io/schema.hpp"
#include "run/run_types.hpp"

namespace fowtsim::driver {

io::Schema floating_scene_schema();
// True if the YAML deck's top level holds a `structure` mapping.
bool is_floating_scene(const std::filesystem::path& deck);
RunReport run_floating_scene(const RunRequest& request, const ProgressCallback& progress);

}  // namespace fowtsim::driver
