#include "fowtsim/beam/beam_state.hpp"

namespace fowtsim::beam {

BeamState make_state(const BeamModel& model) {
  BeamState state;
  for (const NodeModel& node : model.nodes) {
    state.position_m.push_back(node.position_m);
    state.orientation.push_back(node.orientation);
    state.velocity.push_back(Vec6::Zero());
    state.acceleration.push_back(Vec6::Zero());
  }
  return state;
}

}  // namespace fowtsim::beam
