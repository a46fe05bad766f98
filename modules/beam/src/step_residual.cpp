// R = r − M a − C w_c − K w_k of linear_system.hpp without the matrices. Each term below is the
// vector form of a block built in linear_system.cpp (add_node_inertia, add_dead_load) or in
// section_mechanics.cpp; the unit test "the one-pass step matrix and the matrix-free residual
// equal the assembled system" holds them together to rounding.
#include "fowtsim/beam/linear_system.hpp"

#include <Eigen/Geometry>

#include "flow_terms.hpp"
#include "section_mechanics.hpp"
#include "water_terms.hpp"

namespace fowtsim::beam {
namespace {

// Node n's own share: inertia about the node in the moving frame (eqs. 2.57–2.66, see
// linear_system.hpp) and dead loads at their arms. With c the mass-centre offset, A v =
// Ω̇ × v + Ω × (Ω × v), p(v) = v_u − c × v_θ (the mass centre's part of a node motion v) and
// I_G = J_P + m c̃ c̃ the inertia about the mass centre:
//   M v = [m p; m c × v_u + J_P v_θ] = [m p; c × m p + I_G v_θ]
//   C v = [2m Ω × p; c × (2m Ω × p) + Ω × (I_G v_θ) − (I_G Ω) × v_θ + I_G (Ω × v_θ)] + μ_M M v
//   K v = [m A p; c × (m A p) + m a_0 × (c × v_θ) + Ω × (I_G (Ω × v_θ)) − Ω × ((I_G Ω) × v_θ)
//          + I_G (Ω̇ × v_θ) − (I_G Ω̇) × v_θ − Σ f × (arm × v_θ)]
// The three translational parts share the moment arm c and the I_G products are merged, so the
// node costs four 3×3 products.
Vec6 node_residual(const BeamModel& model, const BeamInput& input, const BeamState& state, int n,
                   const Vec6& a, const Vec6& w_c, const Vec6& w_k) {
  const NodeModel& node = model.nodes[n];
  const Mat3& r = state.orientation[n];
  const FrameKinematics& frame = input.frame;
  const double m = node.mass_kg;
  const Vec3 c = r * node.mass_offset_m;
  Mat3 i_g = r * node.inertia_kg_m2 * r.transpose() + m * c * c.transpose();
  i_g.diagonal().array() -= m * c.squaredNorm();
  const Vec3& w = frame.angular_velocity_rad_s;
  const Vec3& w_dot = frame.angular_acceleration_rad_s2;
  const auto frame_a = [&](const Vec3& v) -> Vec3 { return w_dot.cross(v) + w.cross(w.cross(v)); };
  const Vec3 a0 = frame.acceleration_m_s2 - frame.gravity_m_s2 + frame_a(state.position_m[n] + c);
  const Vec3 i_w = i_g * w, i_w_dot = i_g * w_dot;

  const Vec6 mass_weighted = a + model.mass_damping_1_s * w_c;  // − M (a + μ_M w_c)
  const Vec3 th_m = mass_weighted.tail<3>(), th_c = w_c.tail<3>(), th_k = w_k.tail<3>();
  const Vec3 c_th = c.cross(th_k);
  // m a_0 (frame), m p(a + μ_M w_c) (mass), 2m Ω × p(w_c) (Coriolis), m A p(w_k) (stiffness)
  const Vec3 translational = m * (a0 + mass_weighted.head<3>() - c.cross(th_m) +
                                  2.0 * w.cross(w_c.head<3>() - c.cross(th_c)) + frame_a(w_k.head<3>() - c_th));
  Vec3 force = -translational;
  Vec3 moment = -(c.cross(translational) + w.cross(i_w) + i_w_dot + i_g * (th_m + w.cross(th_c) + w_dot.cross(th_k)) +
                  w.cross(i_g * (th_c + w.cross(th_k))) + m * a0.cross(c_th) - i_w.cross(th_c) -
                  w.cross(i_w.cross(th_k)) - i_w_dot.cross(th_k));
  auto dead_load = [&](const Vec6& load, const Vec3& arm) {
    force += load.head<3>();
    moment += load.tail<3>() + arm.cross(load.head<3>()) + load.head<3>().cross(arm.cross(th_k));
  };
  if (!input.node_loads.empty()) dead_load(input.node_loads[n], r * node.load_arm_m);
  if (n == model.node_count() - 1) dead_load(input.tip_load, r * model.tip_arm_m);
  Vec6 out;
  out << force, moment;
  return out;
}

// The increments of a section's two ends from a nodal vector: a held end does not move unless it
// is a tip moved by `tip` (its translation; nullptr: at rest), a pinned end's ghost moves as
// u_g = 2 u_end − u, θ_g = θ of its node (the mirror image through the end point).
Vec6 end_motion(const VecX& q, const SectionModel& sec, int end, int other, const Vec3* tip = nullptr) {
  const auto node = [&](int n) { return n >= 0 ? Vec6(q.segment<6>(6 * n)) : Vec6::Zero(); };
  Vec6 m = end_motion(sec, end, node(other), node(end));
  if (tip && end == kTipEnd) m.head<3>() += (sec.pinned ? 2.0 : 1.0) * *tip;
  return m;
}

// [u_a − u_b; θ_a; θ_b] of a nodal vector, with the held tip's translation `tip` (nullptr: at rest).
Vec9 reduced_pair(const VecX& q, const SectionModel& sec, const Vec3* tip = nullptr) {
  const Vec6 a = end_motion(q, sec, sec.inboard, sec.outboard, tip), b = end_motion(q, sec, sec.outboard, sec.inboard, tip);
  Vec9 out;
  out << a.head<3>() - b.head<3>(), a.tail<3>(), b.tail<3>();
  return out;
}

// Adds a section's loads on its ends to the residual: held ends, and a pin's ghost, go to the support.
void add_section_loads(const SectionModel& sec, const Vec12& loads, VecX& residual) {
  if (sec.outboard >= 0) residual.segment<6>(6 * sec.outboard) += loads.tail<6>();
  if (sec.inboard >= 0) residual.segment<6>(6 * sec.inboard) += loads.head<6>();
}

}  // namespace

void step_residual(const BeamModel& model, const BeamInput& input, const BeamState& state,
                   const VecX& w_c, const VecX& w_k, const VecX& a, VecX& residual, const HeldTipTrial* tip) {
  for (int n = 0; n < model.node_count(); ++n)
    residual.segment<6>(6 * n) = node_residual(model, input, state, n, a.segment<6>(6 * n),
                                               w_c.segment<6>(6 * n), w_k.segment<6>(6 * n));
  if (model.water) {  // the water's blocks (water_terms.hpp) applied to the trial vectors
    Mat6 mass, damping;
    Vec6 rhs;
    for (int n = 0; n < model.node_count(); ++n) {
      mass.setZero();
      damping.setZero();
      rhs.setZero();
      add_water_node_terms(model, input, state, n, true, mass, damping, rhs);
      residual.segment<6>(6 * n) += rhs - mass * a.segment<6>(6 * n) - damping * w_c.segment<6>(6 * n);
    }
  }
  const Vec3* tip_k = tip ? &tip->stiffness_m : nullptr;
  const Vec3* tip_c = tip ? &tip->damping_m_s : nullptr;
  NodePose pa, pb;
  if (!model.flow) {
    for (const SectionModel& sec : model.sections) {
      section_poses(model, state, sec, pa, pb);
      add_section_loads(sec, section_residual_loads(sec, pa, pb, reduced_pair(w_k, sec, tip_k), reduced_pair(w_c, sec, tip_c)),
                        residual);
    }
    return;
  }
  // A pipe: the flow's blocks (flow_terms.hpp) applied to the trial vectors, R += r − M a − C w_c − K w_k,
  // and the pressure and momentum flux as a resultant offset of every section.
  // Workspace kept per thread so that the step allocates only at its first call (face_pressures
  // assigns n + 1 values into it; its capacity stays).
  thread_local std::vector<double> pressures;
  face_pressures(model, input, state, pressures);
  Mat6 mass, damping, stiffness;
  Vec6 rhs;
  for (int n = 0; n < model.node_count(); ++n) {
    mass.setZero();
    damping.setZero();
    stiffness.setZero();
    rhs.setZero();
    add_flow_node_terms(model, input, state, n, pressures.back(), true, mass, damping, stiffness, rhs);
    residual.segment<6>(6 * n) += rhs - mass * a.segment<6>(6 * n) - damping * w_c.segment<6>(6 * n) -
                                  stiffness * w_k.segment<6>(6 * n);
  }
  Mat12 flow_damping;
  for (int j = 0; j < static_cast<int>(model.sections.size()); ++j) {
    const SectionModel& sec = model.sections[j];
    section_poses(model, state, sec, pa, pb);
    const Vec6 offset = flow_section_offset(*model.flow, pressures[j]);
    Vec12 loads = section_residual_loads(sec, pa, pb, reduced_pair(w_k, sec, tip_k), reduced_pair(w_c, sec, tip_c), &offset);
    flow_section_damping(*model.flow, sec, pa, pb, flow_damping);  // zero at a held end
    Vec12 rates;
    rates << end_motion(w_c, sec, sec.inboard, sec.outboard), end_motion(w_c, sec, sec.outboard, sec.inboard);
    loads -= flow_damping * rates;
    add_section_loads(sec, loads, residual);
  }
}

void frame_acceleration_load(const BeamModel& model, const BeamState& state, const VecX& w_k, const Vec3& da,
                             const Vec3& dw_dot, VecX& out) {
  // The derivative of node_residual along (a_f, Ω̇) = (da, dω̇): a_0 grows by da + dω̇ × (x + c)
  // and frame_a(v) by dω̇ × v; every other term is independent of the frame acceleration.
  for (int n = 0; n < model.node_count(); ++n) {
    const NodeModel& node = model.nodes[n];
    const Mat3& r = state.orientation[n];
    const double m = node.mass_kg;
    const Vec3 c = r * node.mass_offset_m;
    Mat3 i_g = r * node.inertia_kg_m2 * r.transpose() + m * c * c.transpose();
    i_g.diagonal().array() -= m * c.squaredNorm();
    const Vec3 th_k = w_k.segment<3>(6 * n + 3);
    const Vec3 c_th = c.cross(th_k);
    const Vec3 d_a0 = da + dw_dot.cross(state.position_m[n] + c);
    const Vec3 d_translational = m * (d_a0 + dw_dot.cross(w_k.segment<3>(6 * n) - c_th));
    const Vec3 i_w_dot = i_g * dw_dot;
    out.segment<3>(6 * n) = -d_translational;
    out.segment<3>(6 * n + 3) =
        -(c.cross(d_translational) + i_w_dot + i_g * dw_dot.cross(th_k) + m * d_a0.cross(c_th) - i_w_dot.cross(th_k));
  }
}

Vec6 root_residual_load(const BeamModel& model, const BeamState& state, const VecX& w_c, const VecX& w_k,
                        const Vec6* root_offset) {
  const SectionModel& sec = model.sections.front();
  NodePose a, b;
  section_poses(model, state, sec, a, b);
  Vec6 load = section_residual_loads(sec, a, b, reduced_pair(w_k, sec), reduced_pair(w_c, sec), root_offset).head<6>();
  if (sec.pinned) load.tail<3>() -= (sec.alpha * (b.position_m - a.position_m)).cross(Vec3(load.head<3>()));
  return load;
}

}  // namespace fowtsim::beam
