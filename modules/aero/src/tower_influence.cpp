#include "fowtsim/aero/tower_influence.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace fowtsim::aero {
namespace {

constexpr double kPi = std::numbers::pi;

struct Station {
  double radius_m, drag_coefficient, turbulence_intensity;
};

// Tower properties at elevation s along the axis, linear between stations, held beyond the ends.
Station station_at(const std::vector<TowerNodeParams>& tower, double s) {
  if (s <= tower.front().elevation_m) {
    const TowerNodeParams& t = tower.front();
    return {0.5 * t.diameter_m, t.drag_coefficient, t.turbulence_intensity};
  }
  if (s >= tower.back().elevation_m) {
    const TowerNodeParams& t = tower.back();
    return {0.5 * t.diameter_m, t.drag_coefficient, t.turbulence_intensity};
  }
  std::size_t i = 0;
  while (tower[i + 1].elevation_m < s) ++i;
  const TowerNodeParams& a = tower[i];
  const TowerNodeParams& b = tower[i + 1];
  const double w = (s - a.elevation_m) / (b.elevation_m - a.elevation_m);
  return {0.5 * (a.diameter_m + w * (b.diameter_m - a.diameter_m)),
          a.drag_coefficient + w * (b.drag_coefficient - a.drag_coefficient),
          a.turbulence_intensity + w * (b.turbulence_intensity - a.turbulence_intensity)};
}

}  // namespace

Vec3 tower_disturbance(const Params& params, const Vec3& tower_base_m, const Vec3& tower_axis,
                       const Vec3& point_m, const Vec3& inflow_m_s) {
  if (params.tower_potential == TowerPotential::none && params.tower_shadow == TowerShadow::none) {
    return Vec3::Zero();
  }
  const Vec3& k = tower_axis;
  const double s = (point_m - tower_base_m).dot(k);
  const double bottom = params.tower.front().elevation_m, top = params.tower.back().elevation_m;
  const double s_near = std::clamp(s, bottom, top);
  const Station st = station_at(params.tower, s_near);
  const double z_bar = std::abs(s - s_near) / st.radius_m;  // axial distance beyond an end [radii]
  if (z_bar >= 1.0) return Vec3::Zero();

  const Vec3 d = point_m - (tower_base_m + s_near * k);  // from the nearest axis point
  const double diameter = 2.0 * st.radius_m;
  const double clearance = d.norm() - st.radius_m;
  if (clearance <= 0.01 * diameter || clearance > 20.0 * diameter) return Vec3::Zero();

  const Vec3 normal_wind = inflow_m_s - inflow_m_s.dot(k) * k;
  const double w = normal_wind.norm();
  if (w < 1e-12) return Vec3::Zero();
  const Vec3 x_hat = normal_wind / w;
  const Vec3 y_hat = k.cross(x_hat);
  const double taper = std::cos(0.5 * kPi * z_bar);  // end taper by coordinate scaling
  const double x = d.dot(x_hat) / st.radius_m / taper;
  const double y = d.dot(y_hat) / st.radius_m / taper;
  const double r2 = x * x + y * y;

  double u = 0.0, v = 0.0;
  if (params.tower_potential == TowerPotential::baseline) {
    u = (y * y - x * x) / (r2 * r2);
    v = -2.0 * x * y / (r2 * r2);
  } else if (params.tower_potential == TowerPotential::bak) {
    const double xb = x + 0.1, rb2 = xb * xb + y * y;
    u = (y * y - xb * xb) / (rb2 * rb2) + st.drag_coefficient * xb / (2.0 * kPi * rb2);
    v = -2.0 * xb * y / (rb2 * rb2) + st.drag_coefficient * y / (2.0 * kPi * rb2);
  }
  double shadow = 0.0;
  if (x > 0.0 && params.tower_shadow == TowerShadow::powles) {
    const double root_r = std::sqrt(std::sqrt(r2));
    if (std::abs(y) <= root_r) {
      const double c = std::cos(0.5 * kPi * y / root_r);
      shadow = -st.drag_coefficient / root_r * c * c;
    }
  } else if (x > 0.0 && params.tower_shadow == TowerShadow::eames) {
    const double width = st.turbulence_intensity * x;
    shadow = -st.drag_coefficient / (width * std::sqrt(2.0 * kPi)) *
             std::exp(-0.5 * (y / width) * (y / width));
  }
  shadow = std::max(shadow, -0.5);
  return w * ((u + shadow) * x_hat + v * y_hat);
}

}  // namespace fowtsim::aero
