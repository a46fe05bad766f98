#pragma once
// One cross-section of the discretised beam (seed 000 §2.4.2): its discrete strains from the two
// nodes it joins (eqs. 2.54–2.55 written with exact finite rotations), the stress resultants
// (eqs. 2.63–2.64), the loads they put on both nodes, and the exact derivative of those loads
// with respect to node increments — the elastic stiffness of Appendix A (eqs. A.1–A.12), derived
// here in spatial increments because the extracted appendix is garbled.
//
// Kinematics. Section j joins node a (inboard) and node b (outboard), distance Δs apart:
//   d = x_b − x_a,  ψ = log(R_aᵀ R_b),  R_j = R_a exp(α ψ̃)   (geodesic interpolation, eq. 2.76)
//   γ = R_jᵀ d/Δs − γ_ref,  κ = ψ/Δs − κ_ref                    (eqs. 2.48–2.49, 2.74–2.75)
// so both strains vanish in the undeformed configuration. Resultants S = [N; M] = C [γ; κ] in
// the section frame; F = R_j N, M = R_j M in f. Loads on the nodes (moments about the node):
//   f_a = F,  m_a = M + α d × F;   f_b = −F,  m_b = −M + (1 − α) d × F,     i.e. loads = G S,
// which balance exactly in total force and moment (momentum is conserved by the assembly).
//
// Increments. x ← x + u, R ← exp(θ̃) R with (u, θ) in f. Then
//   δd = u_b − u_a,  δψ = Ψ (θ_b − θ_a) with Ψ = J_r⁻¹(ψ) R_bᵀ,
//   δφ_j = θ_a + P (θ_b − θ_a) with P = α R_j J_r(αψ) Ψ   (rotation of the section frame),
//   δγ = R_jᵀ (δd + d̃ δφ_j)/Δs,  δκ = δψ/Δs,                   i.e. δ[γ; κ] = B δq.
// The tangent of the loads is G δS + (δG) S: −G C B (material) plus the geometric part at fixed S.
//
// A rigid translation strains nothing, so the u_b columns of B and of every tangent are the
// negated u_a columns: only 9 of the 12 columns are computed ("reduced" columns u_a, θ_a, θ_b,
// acting on [u_a − u_b; θ_a; θ_b]). The section tangents are most of the cost of a step matrix.
#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/beam_state.hpp"
#include "fowtsim/core/types.hpp"

namespace fowtsim::beam {

using Mat12 = Eigen::Matrix<double, 12, 12>;
using Vec12 = Eigen::Matrix<double, 12, 1>;
using Vec9 = Eigen::Matrix<double, 9, 1>;
using Mat6x9 = Eigen::Matrix<double, 6, 9>;
using Mat12x9 = Eigen::Matrix<double, 12, 9>;

struct NodePose {
  Vec3 position_m;
  Mat3 orientation;
};

// The base pose of node n, or of the held root (kRootEnd) or tip (kTipEnd).
inline NodePose node_pose(const BeamModel& model, const BeamState& state, int n) {
  if (n == kRootEnd) return {model.root_position_m, model.root_orientation};
  if (n == kTipEnd) return {model.tip_position_m + state.tip_offset_m, model.tip_orientation};
  return {state.position_m[n], state.orientation[n]};
}

// The base poses of a section's two ends. The held end of a pinned section is the ghost: the
// mirror image of the node through the end point, with the node's orientation.
inline void section_poses(const BeamModel& model, const BeamState& state, const SectionModel& sec, NodePose& a,
                          NodePose& b) {
  a = node_pose(model, state, sec.inboard);
  b = node_pose(model, state, sec.outboard);
  if (!sec.pinned) return;
  if (sec.inboard == kRootEnd) a = {2.0 * a.position_m - b.position_m, b.orientation};
  else b = {2.0 * b.position_m - a.position_m, a.orientation};
}

// The motion (increment, velocity) of a section end: its node's, none for a held end, and for
// a pin's ghost (−u, θ) of the node at the other end.
inline Vec6 end_motion(const SectionModel& sec, int end, const Vec6& other_node_motion, const Vec6& node_motion) {
  if (end >= 0) return node_motion;
  if (!sec.pinned) return Vec6::Zero();
  Vec6 g = other_node_motion;
  g.head<3>() *= -1.0;
  return g;
}

// A section tangent (rows and columns [a; b]) reduced to its real nodes: the ghost of a pinned
// end moves as u_ghost = −u, θ_ghost = θ of its node, and its own rows (the pin's reaction) go to
// the support. Columns of a clamped end are dropped by the scatter.
inline void fold_pinned_end(const SectionModel& sec, Mat12& t) {
  if (!sec.pinned) return;
  const int ghost = sec.inboard == kRootEnd ? 0 : 6, node = 6 - ghost;
  t.block<12, 3>(0, node) -= t.block<12, 3>(0, ghost);
  t.block<12, 3>(0, node + 3) += t.block<12, 3>(0, ghost + 3);
  t.middleRows<6>(ghost).setZero();
  t.middleCols<6>(ghost).setZero();
}

// A section linearised about the base configuration.
struct SectionLinearization {
  double alpha = 0.5;     // section position between the nodes (copied from the model)
  Vec3 chord;             // d = x_b − x_a, in f [m]
  Mat3 orientation;       // R_j: section frame → f
  Vec6 strain;            // [γ; κ] in the section frame
  Vec6 resultant;         // S = C [γ; κ], section frame (elastic only)
  Vec12 node_loads;       // G S = [f_a; m_a; f_b; m_b] in f
  Mat6x9 strain_map;      // B on the reduced columns
  Mat12x9 geometric;      // ∂(node loads)/∂q at fixed S, reduced columns
};

// `offset` (optional, section frame) is added to the elastic resultant: a resultant that does not
// come from the strains, such as the pressure and momentum flux of fluid flowing inside a pipe
// (internal_flow.hpp). It rotates with the section, so it enters the loads and the geometric part.
void linearize_section(const SectionModel& sec, const NodePose& a, const NodePose& b,
                       SectionLinearization& out, const Vec6* offset = nullptr);

// [f_a; m_a; f_b; m_b] of a section-frame resultant s: G s.
Vec12 node_loads_of(const SectionLinearization& lin, const Vec6& s);

// Node increments [u_a; θ_a; u_b; θ_b] → the reduced vector [u_a − u_b; θ_a; θ_b].
Vec9 reduced(const Vec12& q);

// The 12×12 tangent −G W B − g·(geometric part): with W = C, g = 1 the stiffness
// K = −∂(node loads)/∂q; with W = D, g = 0 the strain-rate damping; with W = k C + c D, g = k
// the combination k K + c C_str the implicit step needs, at the cost of one.
void section_tangent(const SectionLinearization& lin, const Mat6& weight, double geometric_weight,
                     Mat12& out);

// The section's share of the step residual r − C w_c − K w_k without forming B, the geometric
// part or the tangent: G (S + C B w_k + D B w_c) + (geometric part) w_k, with B and the
// geometric part applied as the vector formulas they stand for (header, "Increments"). w_k and
// w_c are the reduced node vectors [u_a − u_b; θ_a; θ_b]. Exact to rounding against the matrices.
Vec12 section_residual_loads(const SectionModel& sec, const NodePose& a, const NodePose& b,
                             const Vec9& w_k, const Vec9& w_c, const Vec6* offset = nullptr);

// Loads only, with optional strain-rate damping D B q̇: for outputs and tests.
Vec12 section_loads(const SectionModel& sec, const NodePose& a, const NodePose& b,
                    const Vec6* velocity_a = nullptr, const Vec6* velocity_b = nullptr,
                    const Vec6* offset = nullptr);

}  // namespace fowtsim::beam
