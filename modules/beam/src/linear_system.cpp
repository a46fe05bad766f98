#include "fowtsim/beam/linear_system.hpp"

#include <Eigen/Geometry>

#include "fowtsim/core/rotation.hpp"
#include "section_mechanics.hpp"

namespace fowtsim::beam {
namespace {

NodePose pose_of(const BeamModel& model, const BeamState& state, int node) {
  if (node < 0) return {model.root_position_m, model.root_orientation};
  return {state.position_m[node], state.orientation[node]};
}

// Inertial blocks of one node (eqs. 2.52–2.53 and 2.57–2.66 about the node, see header):
// frame acceleration A = Ω̇̃ + Ω̃Ω̃ and the acceleration a0 of the mass centre at the base.
void add_node_inertia(const NodeModel& node, const Vec3& x, const Mat3& r,
                      const FrameKinematics& frame, Inertia inertia, double mass_damping,
                      Mat6& mass_out, Mat6& damping, Mat6& stiffness, Vec6& rhs) {
  const double m = node.mass_kg;
  const Vec3 c = r * node.mass_offset_m;
  const Mat3 ct = skew(c);
  const Mat3 j_p = r * node.inertia_kg_m2 * r.transpose();
  const Mat3 i_g = j_p + m * ct * ct;  // inertia about the mass centre, in f
  const Vec3& w = frame.angular_velocity_rad_s;
  const Vec3& w_dot = frame.angular_acceleration_rad_s2;
  const Mat3 wt = skew(w);
  const Mat3 a = skew(w_dot) + wt * wt;
  const Vec3 a0 = frame.acceleration_m_s2 - frame.gravity_m_s2 + a * (x + c);

  rhs.head<3>() -= m * a0;
  rhs.tail<3>() -= wt * (i_g * w) + i_g * w_dot + m * ct * a0;

  stiffness.block<3, 3>(0, 0) += m * a;
  stiffness.block<3, 3>(0, 3) -= m * a * ct;
  stiffness.block<3, 3>(3, 0) += m * ct * a;
  stiffness.block<3, 3>(3, 3) += -m * ct * a * ct + m * skew(a0) * ct +
                                 wt * (i_g * wt - skew(i_g * w)) + i_g * skew(w_dot) -
                                 skew(i_g * w_dot);
  if (inertia == Inertia::static_only) return;

  Mat6 mm;
  mm << m * Mat3::Identity(), -m * ct, m * ct, j_p;
  mass_out = mm;
  damping.block<3, 3>(0, 0) += 2.0 * m * wt;
  damping.block<3, 3>(0, 3) -= 2.0 * m * wt * ct;
  damping.block<3, 3>(3, 0) += 2.0 * m * ct * wt;
  damping.block<3, 3>(3, 3) += -2.0 * m * ct * wt * ct + wt * i_g - skew(i_g * w) + i_g * wt;
  damping += mass_damping * mm;
}

// A dead load (force f, moment mo) acting at arm r from the node: moment r × f, and since r turns
// with the node, M(θ) ≈ r × f + f̃ r̃ θ, i.e. stiffness −f̃ r̃.
void add_dead_load(const Vec6& load, const Vec3& arm, Mat6& stiffness, Vec6& rhs) {
  const Vec3 f = load.head<3>();
  rhs.head<3>() += f;
  rhs.tail<3>() += load.tail<3>() + arm.cross(f);
  stiffness.block<3, 3>(3, 3) -= skew(f) * skew(arm);
}

}  // namespace

void LinearizedBeam::resize(int nodes) {
  if (static_cast<int>(mass.size()) == nodes) return;
  mass.assign(nodes, Mat6::Zero());
  damping.resize(nodes);
  stiffness.resize(nodes);
  rhs = VecX::Zero(6 * nodes);
}

void linearize(const BeamModel& model, const BeamInput& input, const BeamState& state,
               Inertia inertia, LinearizedBeam& out) {
  const int n = model.node_count();
  out.resize(n);
  out.damping.set_zero();
  out.stiffness.set_zero();
  out.rhs.setZero();
  for (int i = 0; i < n; ++i) {
    out.mass[i].setZero();
    Vec6 r = Vec6::Zero();
    add_node_inertia(model.nodes[i], state.position_m[i], state.orientation[i], input.frame,
                     inertia, model.mass_damping_1_s, out.mass[i], out.damping.diag(i),
                     out.stiffness.diag(i), r);
    if (!input.node_loads.empty())
      add_dead_load(input.node_loads[i], state.orientation[i] * model.nodes[i].load_arm_m,
                    out.stiffness.diag(i), r);
    out.rhs.segment<6>(6 * i) += r;
  }
  {
    Vec6 r = Vec6::Zero();
    add_dead_load(input.tip_load, state.orientation[n - 1] * model.tip_arm_m,
                  out.stiffness.diag(n - 1), r);
    out.rhs.segment<6>(6 * (n - 1)) += r;
  }

  SectionResult sr;
  for (const SectionModel& sec : model.sections) {
    const int a = sec.inboard, b = sec.outboard;
    evaluate_section(sec, pose_of(model, state, a), pose_of(model, state, b), sr);
    out.rhs.segment<6>(6 * b) += sr.node_loads.tail<6>();
    out.stiffness.diag(b) += sr.stiffness.block<6, 6>(6, 6);
    if (inertia == Inertia::included) out.damping.diag(b) += sr.damping.block<6, 6>(6, 6);
    if (a < 0) continue;  // the clamped root carries no unknowns
    out.rhs.segment<6>(6 * a) += sr.node_loads.head<6>();
    out.stiffness.diag(a) += sr.stiffness.block<6, 6>(0, 0);
    out.stiffness.upper(a) += sr.stiffness.block<6, 6>(0, 6);
    out.stiffness.lower(a) += sr.stiffness.block<6, 6>(6, 0);
    if (inertia == Inertia::static_only) continue;
    out.damping.diag(a) += sr.damping.block<6, 6>(0, 0);
    out.damping.upper(a) += sr.damping.block<6, 6>(0, 6);
    out.damping.lower(a) += sr.damping.block<6, 6>(6, 0);
  }
}

Vec6 root_reaction(const BeamModel& model, const BeamState& state) {
  const SectionModel& sec = model.sections.front();
  const Vec6 at_rest = Vec6::Zero();
  return section_loads(sec, pose_of(model, state, -1), pose_of(model, state, 0), &at_rest,
                       &state.velocity[0])
      .head<6>();
}

}  // namespace fowtsim::beam
