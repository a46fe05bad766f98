#include "fowtsim/aero/rigid_rotor.hpp"

#include <numbers>

#include <Eigen/Geometry>

#include "fowtsim/core/rotation.hpp"

namespace fowtsim::aero {

void place_rigid_rotor(const Params& params, const RigidRotor& rotor, double azimuth_rad,
                       double rotor_speed_rad_s, double pitch_rad, Aero::Input& in) {
  const Mat3 t_gh = rotation_z(rotor.yaw_rad) * rotation_y(rotor.shaft_tilt_rad) * rotation_x(azimuth_rad);
  in.hub_position_m = rotor.hub_position_m;
  in.hub_orientation = t_gh;
  in.rotor_speed_rad_s = rotor_speed_rad_s;
  in.blade_pitch_rad.setConstant(pitch_rad);
  const Vec3 omega = rotor_speed_rad_s * t_gh.col(0);
  const int nb = params.number_of_blades, nn = nodes_per_blade(params);
  for (int b = 0; b < nb; ++b) {
    const Mat3 t_gblade = t_gh * rotation_x(2.0 * std::numbers::pi * b / nb) * rotation_y(-rotor.precone_rad);
    for (int k = 0; k < nn; ++k) {
      const BladeNodeParams& node = params.blade[k];
      const int i = b * nn + k;
      const Mat3 t_gb = t_gblade * rotation_y(node.curve_angle_rad);
      const Vec3 offset(node.curve_ac_m, node.sweep_ac_m, rotor.hub_radius_m + node.span_m);
      in.node_position_m.col(i) = rotor.hub_position_m + t_gblade * offset;
      in.node_orientation[i] = t_gb * rotation_z(-(node.twist_rad + pitch_rad));
      in.node_velocity_m_s.col(i) = omega.cross(Vec3(t_gblade * offset));
    }
  }
}

}  // namespace fowtsim::aero
