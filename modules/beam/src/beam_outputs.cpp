#include "fowtsim/beam/beam_outputs.hpp"

#include "fowtsim/beam/linear_system.hpp"
#include "fowtsim/core/rotation_vector.hpp"

namespace fowtsim::beam {

BeamOutputs beam_outputs(const BeamModel& model, const BeamState& state) {
  BeamOutputs out;
  const int last = model.node_count() - 1;
  const Mat3& r = state.orientation[last];
  // The tip lies half a segment beyond the last node. Carry the curvature change of the last
  // section, κ = (ψ − ψ_ref)/Δs, on to the tip instead of holding the half segment rigid: the
  // tip rotation error drops from O(Δs) (a tip moment bends that half segment too) to O(Δs²).
  const SectionModel& sec = model.sections.back();
  const Mat3& r_in = sec.inboard < 0 ? model.root_orientation : state.orientation[sec.inboard];
  const Vec3 kappa = rotation_vector(r_in.transpose() * r) / sec.length_m - sec.curvature_ref;
  const double h = model.length_m - model.nodes[last].s_m;
  const Mat3 r0 = model.nodes[last].orientation;
  const Mat3 tip_frame = r * rotation_matrix(kappa * h) * r0.transpose() * model.tip_orientation;
  out.tip_position_m = state.position_m[last] + r * (rotation_matrix(0.5 * h * kappa) * model.tip_arm_m);
  out.tip_displacement_m = out.tip_position_m - model.tip_position_m;
  out.tip_rotation_wm = wiener_milenkovic(tip_frame * model.tip_orientation.transpose());
  out.root_load = root_reaction(model, state);
  return out;
}

}  // namespace fowtsim::beam
