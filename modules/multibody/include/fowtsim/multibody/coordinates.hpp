#pragma once
// One generalised coordinate of the state moved by h, as the linearisations (FloatingScene::
// linearised_system, the frequency-domain screening) take their central differences: translations
// in g, rotations about b's axes (so that δq̇ is the body angular velocity), the rotor and generator
// angles, the tower's and blades' elastic modes (Dof, model.hpp).
#include "fowtsim/multibody/model.hpp"
#include "fowtsim/multibody/state.hpp"

namespace fowtsim::multibody {

void displace_coordinate(State& s, int dof, double h);
// The rate of coordinate `dof` moved by h; on a rigid shaft (no generator DOF) the generator turns
// with the rotor.
void change_coordinate_rate(State& s, int dof, double h, bool rigid_shaft);

}  // namespace fowtsim::multibody
