#include "flow_terms.hpp"

#include <Eigen/Geometry>

#include "fowtsim/core/rotation.hpp"

namespace fowtsim::beam {
namespace {

// 2 for the Reynolds-transport Coriolis of the flow, 1 for the seed's eq. 3.17 (internal_flow.hpp).
double coriolis_factor(const InternalFlow& flow) { return flow.seed_momentum_flux ? 1.0 : 2.0; }

// The momentum flux per unit pipe velocity at a face with axis t: m^f V (I − 2 t tᵀ); the seed's
// relative-velocity flux keeps only the axial −2 m^f V t tᵀ.
Mat3 velocity_flux(const InternalFlow& flow, const Vec3& t) {
  const double mv = flow.fluid_mass_per_length_kg_m * flow.velocity_m_s;
  Mat3 w = -2.0 * mv * t * t.transpose();
  if (!flow.seed_momentum_flux) w.diagonal().array() += mv;
  return w;
}

}  // namespace

void face_pressures(const BeamModel& model, const BeamInput& input, const BeamState& state,
                    std::vector<double>& out) {
  const InternalFlow& flow = *model.flow;
  const int n = model.node_count();
  out.assign(n + 1, 0.0);
  const FrameKinematics& frame = input.frame;
  const Vec3& w = frame.angular_velocity_rad_s;
  for (int i = 0; i < n; ++i) {  // out[i + 1] − out[i] = −Δ_i, marching from p_0 = 0
    const Vec3& x = state.position_m[i];
    const Vec3 t = state.orientation[i].col(2);
    const Vec3 a0 = frame.acceleration_m_s2 - frame.gravity_m_s2 + frame.angular_acceleration_rad_s2.cross(x) +
                    w.cross(w.cross(x)) + 2.0 * w.cross(state.velocity[i].head<3>());
    const double ds = model.nodes[i].segment_length_m;
    const double drop = flow.flow_area_m2 > 0.0 ? (flow.friction_per_length_n_m * ds +
                                                   flow.fluid_mass_per_length_kg_m * ds * a0.dot(t)) /
                                                      flow.flow_area_m2
                                                : 0.0;
    out[i + 1] = out[i] - drop;
  }
  const double shift = flow.boundary_pressure_pa - (flow.pressure_at_tip ? out[n] : 0.0);
  for (double& p : out) p += shift;
}

Vec6 flow_section_offset(const InternalFlow& flow, double pressure_pa) {
  Vec6 s = Vec6::Zero();
  s(2) = -(pressure_pa * flow.flow_area_m2 +
           flow.fluid_mass_per_length_kg_m * flow.velocity_m_s * flow.velocity_m_s);
  return s;
}

void add_flow_node_terms(const BeamModel& model, const BeamInput& input, const BeamState& state, int i,
                         double tip_pressure_pa, bool inertia, Mat6& mass, Mat6& damping, Mat6& stiffness,
                         Vec6& rhs) {
  const InternalFlow& flow = *model.flow;
  const Mat3& r = state.orientation[i];
  const Vec3 t = r.col(2);
  const Mat3 tt = skew(t);
  const double m = flow.fluid_mass_per_length_kg_m * model.nodes[i].segment_length_m;  // m^{f,n}
  const double v = flow.velocity_m_s;
  const double c = coriolis_factor(flow);
  const Vec3& w = input.frame.angular_velocity_rad_s;
  const Mat3 wt = skew(w);

  // Coriolis load of the flow, 2 m^f V Ω × t, turning with the node: t(θ) = t + θ × t.
  rhs.head<3>() -= c * m * v * w.cross(t);
  stiffness.block<3, 3>(0, 3) -= c * m * v * (wt * tt);
  if (inertia) {
    mass.block<3, 3>(0, 0) -= m * t * t.transpose();                // axial fluid mass stays (eq. 3.11)
    damping.block<3, 3>(0, 0) -= c * m * (wt * t) * t.transpose();  // nor feels the axial Coriolis
    damping.block<3, 3>(0, 3) -= m * v * tt;                        // d/dt (m^f V t) = m^f V θ̇ × t
  }
  if (i != model.node_count() - 1 || !model.free_tip()) return;

  // The jet leaving the free tip: a follower force −(p A^f + m^f V²) t at the tip point, and the
  // pipe velocity it carries away (applied at the node, as at the faces).
  const Vec3 arm = r * model.tip_arm_m;
  const Vec3 f = flow_section_offset(flow, tip_pressure_pa)(2) * t;
  const Vec3 moment = arm.cross(f);
  rhs.head<3>() += f;
  rhs.tail<3>() += moment;
  stiffness.block<3, 3>(0, 3) += skew(f);
  stiffness.block<3, 3>(3, 3) += skew(moment);
  if (inertia) {
    const Mat3 wf = velocity_flux(flow, t);  // Φ = W (u̇ + θ̇ × arm), −Φ on the node
    damping.block<3, 3>(0, 0) += wf;
    damping.block<3, 3>(0, 3) -= wf * skew(arm);
  }
}

void flow_section_damping(const InternalFlow& flow, const SectionModel& sec, const NodePose& a,
                          const NodePose& b, Mat12& out) {
  out.setZero();
  const Vec3 chord = b.position_m - a.position_m;
  const Mat3 wf = velocity_flux(flow, chord.normalized());
  // A held end is a point at rest in f: the face between it and its node takes the mean of the
  // two, half the node's velocity, as a face between two nodes does (for a pin too, not its
  // ghost's mirrored motion). The convected flux is then skew between neighbours and conserves the
  // energy of a pipe whose ends do not move, as the continuum does (∫ u̇ ṁ u̇' ds = 0); taking
  // the end face at rest instead leaves an energy source ṁ V u̇²/2 at the outlet volume, and held
  // pipes then fluttered well below their divergence speed (u = 2.55 for pinned ends, not π).
  if (sec.inboard >= 0) {
    out.block<3, 3>(0, 0) = (1.0 - sec.alpha) * wf;
    out.block<3, 3>(6, 0) = -(1.0 - sec.alpha) * wf;
  }
  if (sec.outboard >= 0) {
    out.block<3, 3>(0, 6) = sec.alpha * wf;
    out.block<3, 3>(6, 6) = -sec.alpha * wf;
  }
  if (sec.inboard < 0) out.middleRows<6>(0).setZero();
  if (sec.outboard < 0) out.middleRows<6>(6).setZero();
}

}  // namespace fowtsim::beam
