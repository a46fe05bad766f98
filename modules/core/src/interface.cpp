#include "fowtsim/core/interface.hpp"

#include <stdexcept>

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

void RootLoadAverager::add(const RootLoads& loads, double weight) {
  sum_.force_N += weight * loads.force_N;
  sum_.moment_N_m += weight * loads.moment_N_m;
  sum_.point_m += weight * loads.point_m;
  weight_ += weight;
}

RootLoads RootLoadAverager::average() const {
  if (!(weight_ > 0.0)) throw std::logic_error("RootLoadAverager::average() with no samples");
  const double w = 1.0 / weight_;
  return {w * sum_.force_N, w * sum_.moment_N_m, w * sum_.point_m};
}

}  // namespace fowtsim
