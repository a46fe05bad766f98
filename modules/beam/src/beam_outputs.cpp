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
  const SectionModel& sec = model.sections[last];
  const Mat3& r_in = sec.inboard < 0 ? model.root_orientation : state.orientation[sec.inboard];
  const Vec3 kappa = rotation_vector(r_in.transpose() * r) / sec.length_m - sec.curvature_ref;
  const double h = model.length_m - model.nodes[last].s_m;
  const Mat3 r0 = model.nodes[last].orientation;
  const Mat3 tip_frame = r * rotation_matrix(kappa * h) * r0.transpose() * model.tip_orientation;
  out.tip_position_m = state.position_m[last] + r * (rotation_matrix(0.5 * h * kappa) * model.tip_arm_m);
  out.tip_displacement_m = out.tip_position_m - model.tip_position_m;
  out.tip_rotation_wm = wiener_milenkovic(tip_frame * model.tip_orientation.transpose());
  if (!model.free_tip()) {  // a held tip stays at its point; a pinned one turns with the last volume
    out.tip_position_m = model.tip_position_m;
    out.tip_displacement_m.setZero();
    out.tip_rotation_wm = model.sections.back().pinned ? wiener_milenkovic(r * r0.transpose()) : Vec3::Zero();
  }
  out.root_load = root_reaction(model, state);
  return out;
}

namespace {

// Section j sits between node j−1 and node j, at alpha of the way: the one nearest to eta.
const SectionModel& section_nearest(const BeamModel& model, double eta) {
  const double s = eta * model.length_m;
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < model.sections.size(); ++j) {
    const SectionModel& sec = model.sections[j];
    const double s_a = sec.inboard >= 0 ? model.nodes[sec.inboard].s_m : sec.pinned ? -0.5 * sec.length_m : 0.0;
    const double distance = std::abs(s_a + sec.alpha * sec.length_m - s);
    if (distance < best_distance) {
      best_distance = distance;
      best = j;
    }
  }
  return model.sections[best];
}

}  // namespace

Mat3 section_frame_at(const BeamModel& model, const BeamState& state, double eta) {
  const SectionModel& sec = section_nearest(model, eta);
  NodePose a, b;
  section_poses(model, state, sec, a, b);
  SectionLinearization lin;
  linearize_section(sec, a, b, lin);
  return lin.orientation;  // the frame the section's strains and resultant are resolved in
}

Vec6 section_load_at(const BeamModel& model, const BeamState& state, double eta) {
  const SectionModel& sec = section_nearest(model, eta);
  const Vec6 at_rest = Vec6::Zero();
  NodePose a, b;
  section_poses(model, state, sec, a, b);
  // Velocities of the ends (a pin's ghost moves as u_g = −u, θ_g = θ of its node).
  auto velocity = [&](int end, int other) {
    const auto node = [&](int n) { return n >= 0 ? state.velocity[n] : at_rest; };
    return end_motion(sec, end, node(other), node(end));
  };
  const Vec6 va = velocity(sec.inboard, sec.outboard), vb = velocity(sec.outboard, sec.inboard);
  const Vec12 loads = section_loads(sec, a, b, &va, &vb);
  // Loads on the inboard node, moment about it → about the section point x_a + α (x_b − x_a).
  Vec6 out = loads.head<6>();
  out.tail<3>() -= (sec.alpha * (b.position_m - a.position_m)).cross(Vec3(out.head<3>()));
  return out;
}

double strain_energy(const BeamModel& model, const BeamState& state) {
  double energy = 0.0;
  SectionLinearization lin;
  NodePose a, b;
  for (const SectionModel& sec : model.sections) {
    section_poses(model, state, sec, a, b);
    linearize_section(sec, a, b, lin);
    energy += 0.5 * sec.length_m * lin.strain.dot(lin.resultant);
  }
  return energy;
}

}  // namespace fowtsim::beam
