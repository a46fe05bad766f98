#pragma once
// The state the multibody integrates: plain, copyable, fixed size (retry a step, checkpoint,
// perturb). The platform orientation is a unit quaternion so that no attitude is singular
// (Euler 1-2-3 angles lock at θ2 = ±90°); Euler angles are only computed for output.
#include <Eigen/Geometry>

#include "fowtsim/core/types.hpp"
#include "fowtsim/multibody/model.hpp"

namespace fowtsim::multibody {

struct State {
  Vec3 position_m = Vec3::Zero();                   // r: platform reference point in g [m]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // T_gb as a unit quaternion [-]
  Vec3 velocity_m_s = Vec3::Zero();                 // ṙ in g [m/s]
  Vec3 angular_velocity_rad_s = Vec3::Zero();       // ω of the platform, in b [rad/s]
  double rotor_azimuth_rad = 0.0;                   // ψ: rotor about x_s relative to the nacelle [rad], unwrapped
  double rotor_speed_rad_s = 0.0;                   // ψ̇ (LSS) [rad/s]
  double generator_azimuth_rad = 0.0;               // θ_g: generator angle / gearbox ratio (LSS side) [rad]
  double generator_speed_rad_s = 0.0;               // θ̇_g [rad/s]; GenSpeed = N θ̇_g; = ψ̇ with a rigid shaft
  double rotor_acceleration_rad_s2 = 0.0;            // ψ̈, used only when the spin is prescribed [rad/s²]
  double generator_acceleration_rad_s2 = 0.0;        // θ̈_g, likewise [rad/s²]
  double nacelle_yaw_rad = 0.0;                     // nacelle yaw about z_b (prescribed or fixed) [rad]
  double nacelle_yaw_rate_rad_s = 0.0;              // [rad/s]
  double nacelle_yaw_acceleration_rad_s2 = 0.0;     // [rad/s²]
  // Flexible tower: modal coordinates (tower-top deflection of each mode, fore-aft first) [m].
  std::array<double, kMaxTowerModes> tower_deflection_m{};
  std::array<double, kMaxTowerModes> tower_deflection_rate_m_s{};  // [m/s]
  // Rayleigh–Ritz blades: modal coordinates of blade b, flap 1, flap 2, edge 1 (the shapes' tip
  // deflection, ElastoDyn's q) [m], and their rates [m/s].
  std::array<std::array<double, kMaxBladeModes>, kMaxBlades> blade_deflection_m{};
  std::array<std::array<double, kMaxBladeModes>, kMaxBlades> blade_deflection_rate_m_s{};
  // Pitch of each blade (+ toward feather), prescribed: held over a step by the driver [rad]. Turns
  // the Rayleigh–Ritz blades' frames; rigid blades are axisymmetric line masses and ignore it.
  std::array<double, kMaxBlades> blade_pitch_rad{};
};

// Its field list (core/fields.hpp): checkpoints and comparison of states.
template <class Archive>
void fields(Archive& a, State& s) {
  a.io(s.position_m, s.orientation, s.velocity_m_s, s.angular_velocity_rad_s, s.rotor_azimuth_rad,
       s.rotor_speed_rad_s, s.generator_azimuth_rad, s.generator_speed_rad_s, s.rotor_acceleration_rad_s2,
       s.generator_acceleration_rad_s2, s.nacelle_yaw_rad, s.nacelle_yaw_rate_rad_s,
       s.nacelle_yaw_acceleration_rad_s2, s.tower_deflection_m, s.tower_deflection_rate_m_s, s.blade_deflection_m,
       s.blade_deflection_rate_m_s, s.blade_pitch_rad);
}

}  // namespace fowtsim::multibody
