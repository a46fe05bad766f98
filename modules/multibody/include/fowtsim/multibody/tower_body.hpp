#pragma once
// The flexible tower as one Rayleigh–Ritz body of the chain (seed 002 Sec. 2–4): its points move
// with the base body b and bend along the mode directions,
//   x_k = r + T_gb ρ_k,   ρ_k = p_k + Σ_j q_j φ_j(p_k) d_j,
//   v_k = v_r + ω × T_gb ρ_k + T_gb Σ_j φ_kj d_j q̇_j,
// so its Kane terms Σ m J_kᵀ J_k and Σ m J_kᵀ (g − a_k) are sums over the mass that reduce to the
// shape integrals of TowerInertia (the seed's eq. 2 blocks: M_xx = m 1, M_xθ = −s̃, M_θθ = J,
// M_xe = ∫m φ d, M_θe = ∫m ρ̃ φ d, M_ee = ∫m φ φ; velocity-product terms likewise). The cost is
// then independent of how finely the tower's mass is resolved. Everything in g.
#include <array>

#include "fowtsim/core/types.hpp"
#include "fowtsim/multibody/dynamics.hpp"

namespace fowtsim::multibody {

// Adds Σ m J_kᵀ J_k of the tower mass `inertia` describes to `mass`.
void add_tower_mass(const Model& model, const TowerInertia& inertia, const State& state, const ChainKinematics& chain,
                    GeneralisedMatrix& mass);

// The d'Alembert load of that mass: Σ m (g − a_k), its moment Σ (x_k − r) × m (g − a_k) about the
// platform reference point r, and its modal components Σ m φ_kj T_gb d_j · (g − a_k), for the
// generalised accelerations u̇ (u̇ = 0: weight less the velocity-product inertia forces).
struct TowerDAlembert {
  Vec3 force_N = Vec3::Zero();                    // g [N]
  Vec3 moment_N_m = Vec3::Zero();                 // about r, g [N·m]
  std::array<double, kMaxTowerModes> modal_N{};   // [N]
};
TowerDAlembert tower_dalembert(const Model& model, const TowerInertia& inertia, const State& state,
                               const ChainKinematics& chain, const GeneralisedVector& udot, const Vec3& gravity);

// Mass, CM and inertia about the reference point of that mass at the state's deflection, in b.
struct TowerMassProperties {
  double mass_kg = 0.0;                           // [kg]
  Vec3 first_moment_kg_m = Vec3::Zero();          // ∫ m ρ, b [kg·m]
  Mat3 inertia_ref_kg_m2 = Mat3::Zero();          // ∫ m (ρ·ρ 1 − ρ ρᵀ), b [kg·m²]
};
TowerMassProperties tower_mass_properties(const Model& model, const TowerInertia& inertia, const State& state);

// Linear momentum Σ m v_k and angular momentum Σ m x_k × v_k about the origin of g (g).
struct TowerMomentum {
  Vec3 linear_N_s = Vec3::Zero();
  Vec3 angular_N_m_s = Vec3::Zero();
};
TowerMomentum tower_momentum(const Model& model, const TowerInertia& inertia, const State& state,
                             const ChainKinematics& chain);

// A point of the tower at height h above the tower base on the undeflected axis, deflected: its
// position, velocity, Jacobian and bias acceleration (g). Beyond the tower's ends the axis continues
// rigidly: below the base (h < 0) the point moves with the base body, above the top with the top's
// deflection (φ_j taken at the nearer end).
PointKinematics tower_point(const Model& model, const State& state, const ChainKinematics& chain, double height_m);

// The deflection Σ_j q_j φ_j(h) d_j of the tower axis at height h (0 ≤ h ≤ H) relative to the
// undeflected tower, b [m].
Vec3 tower_deflection(const Model& model, const State& state, double height_m);

// The local tower frame at height h (0 ≤ h ≤ H; ElastoDyn's frame t of a tower node): b turned by the
// local slopes as the top frame is (kinematics.cpp), T_gt = T_gb R_x(θ_x) R_y(θ_y) with
// θ_y = Σ_FA φ'_j(h) q_j, θ_x = −Σ_SS φ'_j(h) q_j; T_gb itself for the rigid tower (g ← t).
Mat3 tower_section_orientation(const Model& model, const State& state, const Mat3& t_gb, double height_m);

}  // namespace fowtsim::multibody
