#pragma once
// Node motion of a rigid rotor on a fixed nacelle (AeroDyn-driver-like scenes, the verification
// tests and the benchmark): hub frame, node positions, airfoil-frame orientations and velocities
// from the blade table, the turbine geometry, azimuth, rotor speed and pitch.
//
// Geometry (OpenFAST conventions): shaft frame s = R_z(yaw) R_y(tilt) (x_s downwind along the
// shaft; a nose-up tilt points x_s downward); hub frame h = s R_x(ψ) (azimuth ψ = 0: blade 1 up;
// positive rotation about x_h is clockwise seen from upwind); blade b (0-based) frame
// = h R_x(2π b/B) R_y(−precone) (precone > 0 cones the tips upwind); node frame = blade frame
// R_y(curve_angle); node position = hub + T_g,blade (curve_ac, sweep_ac, hub_radius + span)
// (the blade frame, without the curve angle);
// airfoil frame T_ga = T_gb R_z(−(twist + pitch)).
#include "fowtsim/aero/aero.hpp"

namespace fowtsim::aero {

struct RigidRotor {
  Vec3 hub_position_m = Vec3::Zero();  // rotor apex in g [m]
  double yaw_rad = 0.0;                // nacelle yaw about Z [rad]
  double shaft_tilt_rad = 0.0;         // + nose up [rad] (NREL 5MW: 5°; ElastoDyn ShftTilt = −5°)
  double precone_rad = 0.0;            // + tips upwind [rad] (NREL 5MW: 2.5°; ElastoDyn PreCone = −2.5°)
  double hub_radius_m = 0.0;           // blade root distance from the apex along the pitch axis [m]
};

// Sets the hub pose, rotor speed, pitch (same for all blades) and the node positions,
// orientations and velocities (ω × r, hub at rest) of `input`. Leaves inflow and tower untouched.
// Allocates nothing.
void place_rigid_rotor(const Params& params, const RigidRotor& rotor, double azimuth_rad,
                       double rotor_speed_rad_s, double pitch_rad, Aero::Input& input);

}  // namespace fowtsim::aero
