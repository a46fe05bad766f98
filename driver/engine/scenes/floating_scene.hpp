#pragma once
// The floating-turbine scene: the rigid multibody (platform + tower, nacelle, hub, drivetrain)
// under gravity, hydrodynamics, hydrostatics and mooring in a sea (evaluated at every Runge–Kutta
// stage of the large step; the hydro added mass on the left-hand side), with rigid blades and BEM
// at every stage, or with three flexible MBBT blades, their aerodynamics and the rotor spin at the
// small step (turbine_blades.hpp); the controller at the large step. Rows restore the solvers'
// warm starts they move, so output decimation changes nothing; the scene's whole state can be
// checkpointed (run/checkpoint.hpp). The OC3-Hywind decks in inputs/oc3_hywind and the seed's
// cases in inputs/seed_cases are its verification and load cases.
#include "fowtsim/io/schema.hpp"
#include "run/run_types.hpp"

namespace fowtsim::driver {

io::Schema floating_scene_schema();
RunReport run_floating_scene(const RunRequest& request, const ProgressCallback& progress);

}  // namespace fowtsim::driver
