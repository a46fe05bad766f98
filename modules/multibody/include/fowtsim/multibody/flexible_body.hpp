#pragma once
// A flexible body of the chain (seed 002 Sec. 2–4): its points move with a frame k of the chain —
// origin O (a point of the chain), orientation T_gk, angular velocity and Jacobians of a body of the
// chain — and bend with the body's shape functions,
//   x_k = x_O + T_gk ρ_k,   ρ_k = p_k + Σ_j q_j φ_j(p_k),
//   v_k = v_O + ω × T_gk ρ_k + T_gk Σ_j φ_j(p_k) q̇_j,
// so its Kane terms Σ m J_kᵀ J_k and Σ m J_kᵀ (g − a_k) are sums over the mass that reduce to the
// shape integrals of ShapeIntegrals (the seed's eq. 2 blocks: M_xx = m 1, M_xθ = −s̃, M_θθ = J,
// M_xe = ∫m φ, M_θe = ∫m ρ̃ φ, M_ee = ∫m φᵀφ; velocity-product terms likewise). The cost is then
// independent of how finely the body's mass is resolved. The tower (k = b, O = r) and the
// Rayleigh–Ritz blades (k = the pitched root frame f_i, O = the blade root, turning with the hub)
// are such bodies. Everything in g.
#include <array>

#include "fowtsim/core/types.hpp"
#include "fowtsim/multibody/dynamics.hpp"

namespace fowtsim::multibody {

// Where a flexible body sits in the chain and its modal state.
struct FlexibleBodyMotion {
  const PointKinematics* origin = nullptr;      // O: the frame's origin as a point of the chain
  const RotationKinematics* rotation = nullptr; // the chain body the frame turns with (ω, α, J_ω)
  Mat3 orientation = Mat3::Identity();          // T_gk (a fixed rotation of `rotation`'s frame, e.g. pitch) [-]
  int first_dof = 0;                            // the body's modes are DOFs first_dof … first_dof + mode_count − 1
  int mode_count = 0;
  std::array<double, kMaxBodyModes> q{};        // modal coordinates [m]
  std::array<double, kMaxBodyModes> q_rate{};   // their rates [m/s]
};

// Adds Σ m J_kᵀ J_k of the mass `in` describes to `mass`.
void add_flexible_body_mass(const ShapeIntegrals& in, const FlexibleBodyMotion& body, GeneralisedMatrix& mass);

// The d'Alembert load of that mass: Σ m (g − a_k), its moment Σ (x_k − x_O) × m (g − a_k) about the
// origin O, and its modal components Σ m T_gk φ_kj · (g − a_k), for the generalised accelerations u̇
// (u̇ = 0: weight less the velocity-product inertia forces).
struct FlexibleBodyDAlembert {
  Vec3 force_N = Vec3::Zero();                    // g [N]
  Vec3 moment_N_m = Vec3::Zero();                 // about O, g [N·m]
  std::array<double, kMaxBodyModes> modal_N{};    // [N]
};
FlexibleBodyDAlembert flexible_body_dalembert(const ShapeIntegrals& in, const FlexibleBodyMotion& body,
                                              const GeneralisedVector& udot, const Vec3& gravity);

// Mass, first moment and inertia about O of that mass at the body's deflection, in k.
struct FlexibleBodyMassProperties {
  double mass_kg = 0.0;                           // [kg]
  Vec3 first_moment_kg_m = Vec3::Zero();          // ∫ m ρ, k [kg·m]
  Mat3 inertia_kg_m2 = Mat3::Zero();              // ∫ m (ρ·ρ 1 − ρ ρᵀ) about O, k [kg·m²]
};
FlexibleBodyMassProperties flexible_body_mass_properties(const ShapeIntegrals& in, const FlexibleBodyMotion& body);

// Linear momentum Σ m v_k and angular momentum Σ m x_k × v_k about the origin of g (g).
struct FlexibleBodyMomentum {
  Vec3 linear_N_s = Vec3::Zero();
  Vec3 angular_N_m_s = Vec3::Zero();
};
FlexibleBodyMomentum flexible_body_momentum(const ShapeIntegrals& in, const FlexibleBodyMotion& body);

// A point of the body whose undeflected position is `p` (k, from O) and whose shapes there are
// φ_j = shape[j]: its position, velocity, Jacobian (the modal columns included) and bias
// acceleration (g). The shapes are fixed in k, so the relative motion adds the Coriolis bias
// 2 ω × T_gk Σ φ_j q̇_j and nothing else.
PointKinematics flexible_body_point(const FlexibleBodyMotion& body, const Vec3& p,
                                    const std::array<Vec3, kMaxBodyModes>& shape);

// The same point's position and velocity only (g): what loads that depend on the motion need, without
// the Jacobian's cost.
struct PointMotion {
  Vec3 position_m = Vec3::Zero();
  Vec3 velocity_m_s = Vec3::Zero();
};
PointMotion flexible_body_point_motion(const FlexibleBodyMotion& body, const Vec3& p,
                                       const std::array<Vec3, kMaxBodyModes>& shape);

}  // namespace fowtsim::multibody
