#pragma once
// The terms of the surrounding water (surrounding_water.hpp) on node i's blocks: buoyancy and the
// drag load into rhs, added mass into mass and the drag tangent into damping (these two only with
// `inertia`). linear_system.cpp adds them to the assembled matrices and step_residual.cpp applies
// the same blocks to vectors, as for the flow.
#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/beam_state.hpp"

namespace fowtsim::beam {

void add_water_node_terms(const BeamModel& model, const BeamInput& input, const BeamState& state, int i, bool inertia,
                          Mat6& mass, Mat6& damping, Vec6& rhs);

}  // namespace fowtsim::beam
