#include "fowtsim/aero/rigid_rotor.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace fowtsim::aero {
namespace {

Mat3 rot_x(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Mat3 r;
  r << 1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c;
  return r;
}
Mat3 rot_y(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Mat3 r;
  r << c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c;
  return r;
}
Mat3 rot_z(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Mat3 r;
  r << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  return r;
}

}  // namespace

void place_rigid_rotor(const Params& params, const RigidRotor& rotor, double azimuth_rad,
                       double rotor_speed_rad_s, double pitch_rad, Aero::Input& in) {
  const Mat3 t_gh = rot_z(rotor.yaw_rad) * rot_y(rotor.shaft_tilt_rad) * rot_x(azimuth_rad);
  in.hub_position_m = rotor.hub_position_m;
  in.hub_orientation = t_gh;
  in.rotor_speed_rad_s = rotor_speed_rad_s;
  in.blade_pitch_rad.setConstant(pitch_rad);
  const Vec3 omega = rotor_speed_rad_s * t_gh.col(0);
  const int nb = params.number_of_blades, nn = nodes_per_blade(params);
  for (int b = 0; b < nb; ++b) {
    const Mat3 t_gblade = t_gh * rot_x(2.0 * std::numbers::pi * b / nb) * rot_y(-rotor.precone_rad);
    for (int k = 0; k < nn; ++k) {
      const BladeNodeParams& node = params.blade[k];
      const int i = b * nn + k;
      const Mat3 t_gb = t_gblade * rot_y(node.curve_angle_rad);
      const Vec3 offset(node.curve_ac_m, node.sweep_ac_m, rotor.hub_radius_m + node.span_m);
      in.node_position_m.col(i) = rotor.hub_position_m + t_gblade * offset;
      in.node_orientation[i] = t_gb * rot_z(-(node.twist_rad + pitch_rad));
      in.node_velocity_m_s.col(i) = omega.cross(Vec3(t_gblade * offset));
    }
  }
}

}  // namespace fowtsim::aero
