#include "fowtsim/beam/beam_outputs.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "fowtsim/beam/linear_system.hpp"
#include "fowtsim/core/rotation_vector.hpp"
#include "section_mechanics.hpp"

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

Vec6 section_load_at(const BeamModel& model, const BeamState& state, double eta) {
  // Section j sits between node j−1 and node j, at alpha of the way; pick the nearest to s.
  const double s = eta * model.length_m;
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < model.sections.size(); ++j) {
    const SectionModel& sec = model.sections[j];
    const double s_a = sec.inboard < 0 ? 0.0 : model.nodes[sec.inboard].s_m;
    const double distance = std::abs(s_a + sec.alpha * sec.length_m - s);
    if (distance < best_distance) {
      best_distance = distance;
      best = j;
    }
  }
  const SectionModel& sec = model.sections[best];
  const Vec6 at_rest = Vec6::Zero();
  const NodePose a = node_pose(model, state, sec.inboard), b = node_pose(model, state, sec.outboard);
  const Vec12 loads = section_loads(sec, a, b, sec.inboard < 0 ? &at_rest : &state.velocity[sec.inboard],
                                    &state.velocity[sec.outboard]);
  // Loads on the inboard node, moment about it → about the section point x_a + α (x_b − x_a).
  Vec6 out = loads.head<6>();
  out.tail<3>() -= (sec.alpha * (b.position_m - a.position_m)).cross(Vec3(out.head<3>()));
  return out;
}

double strain_energy(const BeamModel& model, const BeamState& state) {
  double energy = 0.0;
  SectionLinearization lin;
  for (const SectionModel& sec : model.sections) {
    linearize_section(sec, node_pose(model, state, sec.inboard), node_pose(model, state, sec.outboard), lin);
    energy += 0.5 * sec.length_m * lin.strain.dot(lin.resultant);
  }
  return energy;
}

}  // namespace fowtsim::beam
