#pragma once
// The flexible tower as one Rayleigh–Ritz body of the chain (flexible_body.hpp): its points move
// with the base body b from the platform reference point r and bend along the mode directions,
//   ρ_k = p_k + Σ_j q_j φ_j(h_k) d_j   (d_j = x_b fore-aft, y_b side-side),
// so its inertia is flexible_body.hpp's with T_gk = T_gb and O = r. Everything in g.
#include "fowtsim/core/types.hpp"
#include "fowtsim/multibody/flexible_body.hpp"

namespace fowtsim::multibody {

// The tower (or the part of it that `ShapeIntegrals` describe: a gauge's mass above) as a flexible
// body of the chain: O = r, frame b, modes from kTower.
FlexibleBodyMotion tower_motion(const Model& model, const State& state, const ChainKinematics& chain);

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
