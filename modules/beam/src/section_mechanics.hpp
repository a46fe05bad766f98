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
//   f_a = F,  m_a = M + α d × F;   f_b = −F,  m_b = −M + (1 − α) d × F,
// which balance exactly in total force and moment (momentum is conserved by the assembly).
//
// Increments. x ← x + u, R ← exp(θ̃) R with (u, θ) in f. Then
//   δd = u_b − u_a,  δψ = Ψ (θ_b − θ_a) with Ψ = J_r⁻¹(ψ) R_bᵀ,
//   δφ_j = θ_a + P (θ_b − θ_a) with P = α R_j J_r(αψ) Ψ   (rotation of the section frame),
//   δγ = R_jᵀ (δd + d̃ δφ_j)/Δs,  δκ = δψ/Δs.
#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/core/types.hpp"

namespace fowtsim::beam {

using Mat12 = Eigen::Matrix<double, 12, 12>;
using Mat6x12 = Eigen::Matrix<double, 6, 12>;
using Vec12 = Eigen::Matrix<double, 12, 1>;

struct NodePose {
  Vec3 position_m;
  Mat3 orientation;
};

struct SectionResult {
  Vec6 strain;       // [γ; κ] in the section frame
  Vec6 resultant;    // S = C [γ; κ] (+ D [γ̇; κ̇] when velocities are given), section frame
  Vec12 node_loads;  // [f_a; m_a; f_b; m_b] in f: loads the section puts on its two nodes
  Mat6x12 strain_map;  // B: δ[γ; κ] = B δ[u_a; θ_a; u_b; θ_b]
  Mat12 stiffness;   // K = −∂ node_loads / ∂ increments (material + geometric)
  Mat12 damping;     // C_str = −G D B: strain-rate damping, node loads per node velocity
};

// Loads and tangents of one section at the base configuration (no damping load: the step solve
// carries strain-rate damping in the damping matrix).
void evaluate_section(const SectionModel& sec, const NodePose& a, const NodePose& b,
                      SectionResult& out);

// Loads only (no tangent), with optional strain-rate damping: for outputs and tests.
Vec12 section_loads(const SectionModel& sec, const NodePose& a, const NodePose& b,
                    const Vec6* velocity_a = nullptr, const Vec6* velocity_b = nullptr);

}  // namespace fowtsim::beam
