#include "fowtsim/beam/beam_outputs.hpp"

#include "fowtsim/beam/linear_system.hpp"
#include "fowtsim/core/rotation_vector.hpp"

namespace fowtsim::beam {

BeamOutputs beam_outputs(const BeamModel& model, const BeamState& state) {
  BeamOutputs out;
  const int last = model.node_count() - 1;
  const Mat3& r = state.orientation[last];
  out.tip_position_m = state.position_m[last] + r * model.tip_arm_m;
  out.tip_displacement_m = out.tip_position_m - model.tip_position_m;
  // The tip moves rigidly with the last node: R_tip R0_tipᵀ = R_n R0_nᵀ.
  out.tip_rotation_wm = wiener_milenkovic(r * model.nodes[last].orientation.transpose());
  out.root_load = root_reaction(model, state);
  return out;
}

}  // namespace fowtsim::beam
