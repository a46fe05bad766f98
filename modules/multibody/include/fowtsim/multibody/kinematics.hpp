#pragma once
// Exact large-rotation kinematics of the chain (model.hpp) as velocity-transformation
// (Jacobian) form: every point velocity is v = J_v u and every angular velocity ω = J_ω u +
// prescribed part, and every acceleration is a = a_bias + J u̇ with a_bias the velocity-product
// (centripetal, Coriolis, gyroscopic) and prescribed-yaw terms, computed recursively from the base
// outwards by the rigid-body rules v_P = v_O + ω × ρ, a_P = a_O + α × ρ + ω × (ω × ρ) and
// ω_child = ω_parent + θ̇ e, α_child = α_parent + θ̈ e + ω_parent × θ̇ e (e.g. Shabana,
// Dynamics of Multibody Systems, 3rd ed., §2.6 and §3.4; seed 002's velocity-transformation
// matrices). Everything is resolved in the inertial frame g.
#include <array>

#include "fowtsim/core/interface.hpp"
#include "fowtsim/core/types.hpp"
#include "fowtsim/multibody/model.hpp"
#include "fowtsim/multibody/state.hpp"

namespace fowtsim::multibody {

using GeneralisedVector = Eigen::Matrix<double, kMaxDofs, 1>;  // u or u̇; entries ≥ dof_count are 0
using Jacobian = Eigen::Matrix<double, 3, kMaxDofs>;           // ∂(velocity)/∂u, g

struct PointKinematics {
  Vec3 position_m = Vec3::Zero();            // in g [m]
  Vec3 velocity_m_s = Vec3::Zero();          // in g [m/s]
  Vec3 bias_acceleration_m_s2 = Vec3::Zero();  // acceleration at u̇ = 0, g [m/s²]
  Jacobian jacobian = Jacobian::Zero();      // J_v: velocity = J_v u (+ prescribed yaw part in bias) [m]
};

struct RotationKinematics {
  Mat3 orientation = Mat3::Identity();       // T_gk [-]
  Vec3 angular_velocity_rad_s = Vec3::Zero();  // ω_k in g [rad/s]
  Vec3 bias_angular_acceleration_rad_s2 = Vec3::Zero();  // α_k at u̇ = 0, g [rad/s²]
  Jacobian jacobian = Jacobian::Zero();      // J_ω: ω = J_ω u + prescribed yaw rate part [-]
};

// Every Jacobian here has non-zero columns only among the first kBlade DOFs (platform, rotor,
// generator, tower modes): the Rayleigh–Ritz blades' modes enter through their own points
// (blade_body.hpp). The mass assembly relies on it.
struct ChainKinematics {
  RotationKinematics base;                   // b
  RotationKinematics tower_top_frame;        // tower-top frame (= b with a rigid tower; tilted by the slopes)
  RotationKinematics nacelle;                // n (yaw)
  RotationKinematics shaft;                  // s (non-rotating, moves with n)
  RotationKinematics rotor;                  // h
  RotationKinematics generator;              // generator rotor (orientation = T_gs, it is axisymmetric)
  PointKinematics reference;                 // platform reference point r
  PointKinematics base_cm;                   // CM of the base body
  PointKinematics tower_cm;                  // CM of the tower (+ yaw-bearing mass)
  PointKinematics tower_base;                // tower-base point
  PointKinematics tower_top;                 // yaw bearing
  PointKinematics nacelle_cm;
  PointKinematics imu;                       // nacelle IMU
  PointKinematics apex;                      // rotor apex (on the shaft axis)
  PointKinematics rotor_cm;
  std::array<PointKinematics, kMaxBlades> blade_root{};   // root points
  std::array<Mat3, kMaxBlades> blade_root_orientation{};  // T_g,r_i [-]
  std::array<Mat3, kMaxBlades> blade_frame_orientation{}; // pitched root frame T_g,f_i = T_g,r_i R_z(−β_i) [-]
};

// Generalised velocities u of a state (model.hpp Dof order); u[kGenerator] = 0 with a rigid shaft.
GeneralisedVector generalised_velocities(const Model& model, const State& state);

// Positions, velocities, Jacobians and bias accelerations of the whole chain. Allocates nothing.
void chain_kinematics(const Model& model, const State& state, ChainKinematics& out);

// The point where the tower axis (through the tower base, along z_b) crosses elevation 0 in g —
// what aerodynamic tower-influence models take as the tower's origin; the platform reference
// point only when that lies at elevation 0.
Vec3 tower_axis_at_sea_level(const ChainKinematics& chain);

// The point on body `body` at `position_m` (g), with body's reference point `origin`.
PointKinematics point_on(const PointKinematics& origin, const RotationKinematics& body,
                         const Vec3& position_m);

// Full acceleration a = a_bias + J u̇ of a point / angular acceleration of a body (g).
inline Vec3 acceleration(const PointKinematics& p, const GeneralisedVector& udot) {
  return p.bias_acceleration_m_s2 + p.jacobian * udot;
}
inline Vec3 angular_acceleration(const RotationKinematics& r, const GeneralisedVector& udot) {
  return r.bias_angular_acceleration_rad_s2 + r.jacobian * udot;
}

// Motion of a frame (core::FrameMotion conventions: velocity and acceleration in g, angular
// velocity and acceleration in the moving frame) located at point p and rotating with body.
FrameMotion frame_motion(const PointKinematics& p, const RotationKinematics& body,
                         const Mat3& orientation, const GeneralisedVector& udot);

}  // namespace fowtsim::multibody
