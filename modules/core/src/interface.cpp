#include "fowtsim/core/interface.hpp"

#include <Eigen/Geometry>

#include "fowtsim/core/interpolation.hpp"

namespace fowtsim {

FrameMotion interpolate(const FrameMotion& a, const FrameMotion& b, double s) {
  FrameMotion m;
  m.position_m = lerp(a.position_m, b.position_m, s);
  const Eigen::Quaterniond qa(a.orientation), qb(b.orientation);
  m.orientation = qa.slerp(s, qb).toRotationMatrix();
  m.velocity_m_s = lerp(a.velocity_m_s, b.velocity_m_s, s);
  m.acceleration_m_s2 = lerp(a.acceleration_m_s2, b.acceleration_m_s2, s);
  m.angular_velocity_rad_s = lerp(a.angular_velocity_rad_s, b.angular_velocity_rad_s, s);
  m.angular_acceleration_rad_s2 = lerp(a.angular_acceleration_rad_s2, b.angular_acceleration_rad_s2, s);
  return m;
}

}  // namespace fowtsim
