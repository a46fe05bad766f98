#include "fowtsim/beam/tip_motion.hpp"

#include <cmath>
#include <numbers>

namespace fowtsim::beam {

Vec3 RampAndSway::displacement(double t) const {
  const double stretch = t <= 0.0 ? 0.0 : t < stretch_time_s ? stretch_m * t / stretch_time_s : stretch_m;
  const double sway =
      t < sway_start_s ? 0.0 : sway_amplitude_m * std::sin(2.0 * std::numbers::pi * (t - sway_start_s) / sway_period_s);
  return stretch * axis + sway * sway_direction;
}

Vec3 RampAndSway::velocity(double t) const {
  const double stretch = t >= 0.0 && t < stretch_time_s ? stretch_m / stretch_time_s : 0.0;
  const double w = 2.0 * std::numbers::pi / sway_period_s;
  const double sway = t < sway_start_s ? 0.0 : sway_amplitude_m * w * std::cos(w * (t - sway_start_s));
  return stretch * axis + sway * sway_direction;
}

}  // namespace fowtsim::beam
