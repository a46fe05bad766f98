#include "fowtsim/multibody/coordinates.hpp"

#include <Eigen/Geometry>

namespace fowtsim::multibody {

void displace_coordinate(State& b, int k, double h) {
  if (k < 3) b.position_m[k] += h;
  else if (k < 6) b.orientation = (b.orientation * Eigen::Quaterniond(Eigen::AngleAxisd(h, Vec3::Unit(k - 3)))).normalized();
  else if (k == kRotor) b.rotor_azimuth_rad += h;
  else if (k == kGenerator) b.generator_azimuth_rad += h;
  else if (k < kBlade) b.tower_deflection_m[k - kTower] += h;
  else b.blade_deflection_m[(k - kBlade) / kMaxBladeModes][(k - kBlade) % kMaxBladeModes] += h;
}

void change_coordinate_rate(State& b, int k, double h, bool rigid_shaft) {
  if (k < 3) b.velocity_m_s[k] += h;
  else if (k < 6) b.angular_velocity_rad_s[k - 3] += h;
  else if (k == kRotor) b.rotor_speed_rad_s += h;
  else if (k == kGenerator) b.generator_speed_rad_s += h;
  else if (k < kBlade) b.tower_deflection_rate_m_s[k - kTower] += h;
  else b.blade_deflection_rate_m_s[(k - kBlade) / kMaxBladeModes][(k - kBlade) % kMaxBladeModes] += h;
  if (rigid_shaft) b.generator_speed_rad_s = b.rotor_speed_rad_s;
}

}  // namespace fowtsim::multibody
