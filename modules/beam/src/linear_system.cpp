#include "fowtsim/beam/linear_system.hpp"

#include <Eigen/Geometry>

#include "flow_terms.hpp"
#include "fowtsim/core/rotation.hpp"
#include "section_mechanics.hpp"
#include "water_terms.hpp"

namespace fowtsim::beam {
namespace {

// Inertial blocks of one node (eqs. 2.52–2.53 and 2.57–2.66 about the node, see header):
// frame acceleration A = Ω̇̃ + Ω̃Ω̃ and the acceleration a0 of the mass centre at the base.
void add_node_inertia(const NodeModel& node, const Vec3& x, const Mat3& r,
                      const FrameKinematics& frame, Inertia inertia, double mass_damping,
                      Mat6& mass_out, Mat6& damping, Mat6& stiffness, Vec6& rhs) {
  const double m = node.mass_kg;
  const Vec3 c = r * node.mass_offset_m;
  const Mat3 ct = skew(c);
  const Mat3 j_p = r * node.inertia_kg_m2 * r.transpose();
  const Mat3 i_g = j_p + m * skew_product(c, c);  // inertia about the mass centre, in f
  const Vec3& w = frame.angular_velocity_rad_s;
  const Vec3& w_dot = frame.angular_acceleration_rad_s2;
  const Mat3 wt = skew(w);
  const Mat3 a = skew(w_dot) + skew_product(w, w);
  const Vec3 a0 = frame.acceleration_m_s2 - frame.gravity_m_s2 + a * (x + c);
  const Vec3 i_w = i_g * w;
  const Mat3 ct_a = ct * a;
  const Mat3 wt_i = wt * i_g;

  rhs.head<3>() -= m * a0;
  rhs.tail<3>() -= w.cross(i_w) + i_g * w_dot + m * c.cross(a0);

  stiffness.block<3, 3>(0, 0) += m * a;
  stiffness.block<3, 3>(0, 3) -= m * (a * ct);
  stiffness.block<3, 3>(3, 0) += m * ct_a;
  stiffness.block<3, 3>(3, 3) += -m * (ct_a * ct) + m * skew_product(a0, c) + wt_i * wt -
                                 skew_product(w, i_w) + i_g * skew(w_dot) - skew(i_g * w_dot);
  if (inertia == Inertia::static_only) return;

  Mat6 mm;
  mm << m * Mat3::Identity(), -m * ct, m * ct, j_p;
  mass_out = mm;
  damping.block<3, 3>(0, 0) += 2.0 * m * wt;
  damping.block<3, 3>(0, 3) -= 2.0 * m * skew_product(w, c);
  damping.block<3, 3>(3, 0) += 2.0 * m * skew_product(c, w);
  damping.block<3, 3>(3, 3) += -2.0 * m * (skew_product(c, w) * ct) + wt_i - skew(i_w) + i_g * wt;
  damping += mass_damping * mm;
}

// A dead load (force f, moment mo) acting at arm r from the node: moment r × f, and since r turns
// with the node, M(θ) ≈ r × f + f̃ r̃ θ, i.e. stiffness −f̃ r̃.
void add_dead_load(const Vec6& load, const Vec3& arm, Mat6& stiffness, Vec6& rhs) {
  const Vec3 f = load.head<3>();
  rhs.head<3>() += f;
  rhs.tail<3>() += load.tail<3>() + arm.cross(f);
  stiffness.block<3, 3>(3, 3) -= skew_product(f, arm);
}

// The 6×6 blocks node i contributes on its own: inertia and dead loads (node and tip).
struct NodeBlocks {
  Mat6 mass, damping, stiffness;
  Vec6 rhs;
};

// `pressures`: the pipe's face pressures (face_pressures), empty for a beam.
void node_blocks(const BeamModel& model, const BeamInput& input, const BeamState& state, int i,
                 Inertia inertia, const std::vector<double>& pressures, NodeBlocks& out) {
  out.mass.setZero();
  out.damping.setZero();
  out.stiffness.setZero();
  out.rhs.setZero();
  add_node_inertia(model.nodes[i], state.position_m[i], state.orientation[i], input.frame, inertia,
                   model.mass_damping_1_s, out.mass, out.damping, out.stiffness, out.rhs);
  if (!input.node_loads.empty())
    add_dead_load(input.node_loads[i], state.orientation[i] * model.nodes[i].load_arm_m,
                  out.stiffness, out.rhs);
  if (i == model.node_count() - 1)
    add_dead_load(input.tip_load, state.orientation[i] * model.tip_arm_m, out.stiffness, out.rhs);
  if (model.flow)
    add_flow_node_terms(model, input, state, i, pressures.back(), inertia == Inertia::included, out.mass,
                        out.damping, out.stiffness, out.rhs);
  if (model.water)
    add_water_node_terms(model, input, state, i, inertia == Inertia::included, out.mass, out.damping, out.rhs);
}

// The pipe's face pressures (empty for a beam), in a workspace kept per thread so that a step
// allocates only at its first call; valid until the next call. And the resultant offset of section
// j (nullptr for a beam).
const std::vector<double>& pressures_of(const BeamModel& model, const BeamInput& input, const BeamState& state) {
  thread_local std::vector<double> p;
  p.clear();
  if (model.flow) face_pressures(model, input, state, p);
  return p;
}

const Vec6* section_offset(const BeamModel& model, const std::vector<double>& pressures, int j, Vec6& storage) {
  if (!model.flow) return nullptr;
  storage = flow_section_offset(*model.flow, pressures[j]);
  return &storage;
}

// Adds a section's 12×12 tangent to the blocks of its nodes (a or b < 0: a held end).
void scatter(const Mat12& t, int a, int b, BlockTridiagonal& m) {
  if (b >= 0) m.diag(b) += t.block<6, 6>(6, 6);
  if (a >= 0) m.diag(a) += t.block<6, 6>(0, 0);
  if (a < 0 || b < 0) return;
  m.upper(a) = t.block<6, 6>(0, 6);  // each off-diagonal block belongs to one section
  m.lower(a) = t.block<6, 6>(6, 0);
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
  const std::vector<double>& pressures = pressures_of(model, input, state);
  NodeBlocks nb;
  for (int i = 0; i < n; ++i) {
    node_blocks(model, input, state, i, inertia, pressures, nb);
    out.mass[i] = nb.mass;
    out.damping.diag(i) = nb.damping;
    out.stiffness.diag(i) = nb.stiffness;
    out.rhs.segment<6>(6 * i) = nb.rhs;
  }
  if (inertia == Inertia::static_only) out.damping.set_zero();

  SectionLinearization lin;
  Mat12 tangent, flow_damping;
  Vec6 offset;
  NodePose pa, pb;
  for (int j = 0; j < static_cast<int>(model.sections.size()); ++j) {
    const SectionModel& sec = model.sections[j];
    const int a = sec.inboard, b = sec.outboard;
    section_poses(model, state, sec, pa, pb);
    linearize_section(sec, pa, pb, lin, section_offset(model, pressures, j, offset));
    if (b >= 0) out.rhs.segment<6>(6 * b) += lin.node_loads.tail<6>();
    if (a >= 0) out.rhs.segment<6>(6 * a) += lin.node_loads.head<6>();
    section_tangent(lin, sec.stiffness, 1.0, tangent);
    fold_pinned_end(sec, tangent);
    scatter(tangent, a, b, out.stiffness);
    if (inertia == Inertia::static_only) continue;
    section_tangent(lin, sec.damping, 0.0, tangent);
    if (model.flow) {
      flow_section_damping(*model.flow, sec, pa, pb, flow_damping);
      tangent += flow_damping;
    }
    fold_pinned_end(sec, tangent);
    scatter(tangent, a, b, out.damping);
  }
}

void assemble_step_matrix(const BeamModel& model, const BeamInput& input, const BeamState& state,
                          const StepWeights& w, BlockTridiagonal& lhs) {
  const std::vector<double>& pressures = pressures_of(model, input, state);
  NodeBlocks nb;
  for (int i = 0; i < model.node_count(); ++i) {
    node_blocks(model, input, state, i, Inertia::included, pressures, nb);
    lhs.diag(i) = w.mass * nb.mass + w.damping * nb.damping + w.stiffness * nb.stiffness;
  }
  // Per section: k K + c C = −G (k C + c D) B − k·geometric.
  SectionLinearization lin;
  Mat12 tangent, flow_damping;
  Vec6 offset;
  NodePose pa, pb;
  for (int j = 0; j < static_cast<int>(model.sections.size()); ++j) {
    const SectionModel& sec = model.sections[j];
    section_poses(model, state, sec, pa, pb);
    linearize_section(sec, pa, pb, lin, section_offset(model, pressures, j, offset));
    section_tangent(lin, w.stiffness * sec.stiffness + w.damping * sec.damping, w.stiffness, tangent);
    if (model.flow) {
      flow_section_damping(*model.flow, sec, pa, pb, flow_damping);
      tangent += w.damping * flow_damping;
    }
    fold_pinned_end(sec, tangent);
    scatter(tangent, sec.inboard, sec.outboard, lhs);
  }
}

bool root_flow_offset(const BeamModel& model, const BeamInput& input, const BeamState& state, Vec6& out) {
  if (!model.flow) return false;
  out = flow_section_offset(*model.flow, pressures_of(model, input, state).front());
  return true;
}

Vec6 root_reaction(const BeamModel& model, const BeamState& state) {
  const SectionModel& sec = model.sections.front();
  const Vec6 at_rest = Vec6::Zero();
  NodePose a, b;
  section_poses(model, state, sec, a, b);
  const Vec6 root_motion = end_motion(sec, kRootEnd, state.velocity[0], at_rest);
  Vec6 load = section_loads(sec, a, b, &root_motion, &state.velocity[0]).head<6>();
  // About the root point: for a pin the loads on the ghost act at the section, on the end point.
  if (sec.pinned) load.tail<3>() -= (sec.alpha * (b.position_m - a.position_m)).cross(Vec3(load.head<3>()));
  return load;
}

}  // namespace fowtsim::beam
