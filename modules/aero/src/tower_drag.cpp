#include "fowtsim/aero/tower_drag.hpp"

#include <cstddef>

#include <Eigen/Geometry>

namespace fowtsim::aero {

void tower_station_positions(const Params& params, const Vec3& tower_base_m, const Vec3& tower_axis,
                             std::span<Vec3> out) {
  for (std::size_t i = 0; i < params.tower.size(); ++i) out[i] = tower_base_m + params.tower[i].elevation_m * tower_axis;
}

namespace {

// Load per unit length at station i.
Vec3 drag_per_length(const Params& params, const Vec3& tower_axis, const Vec3& velocity_m_s, const Vec3& inflow_m_s,
                     std::size_t i) {
  const Vec3 relative = inflow_m_s - velocity_m_s;
  const Vec3 normal = relative - relative.dot(tower_axis) * tower_axis;
  const TowerNodeParams& t = params.tower[i];
  return 0.5 * params.air_density_kg_m3 * t.drag_coefficient * t.diameter_m * normal.norm() * normal;
}

}  // namespace

TowerDragLoad tower_drag(const Params& params, const Vec3& tower_axis, std::span<const Vec3> position_m,
                         std::span<const Vec3> velocity_m_s, std::span<const Vec3> inflow_m_s, const Vec3& about_m) {
  TowerDragLoad load;
  const std::size_t n = params.tower.size();
  // Load per unit length at station i, and its moment density about `about_m`.
  auto per_length = [&](std::size_t i, Vec3& f, Vec3& m) {
    f = drag_per_length(params, tower_axis, velocity_m_s[i], inflow_m_s[i], i);
    m = (position_m[i] - about_m).cross(f);
  };
  Vec3 f0, m0, f1, m1;
  if (n < 2) return load;
  per_length(0, f0, m0);
  for (std::size_t i = 1; i < n; ++i) {
    per_length(i, f1, m1);
    const double length = params.tower[i].elevation_m - params.tower[i - 1].elevation_m;
    // Both f and r × f vary along the element; with f linear, r × f is quadratic in the elevation,
    // and its exact integral is the trapezoid's less L (Δr × Δf)/6.
    const Vec3 dr = position_m[i] - position_m[i - 1];
    load.force_N += 0.5 * length * (f0 + f1);
    load.moment_N_m += 0.5 * length * (m0 + m1) - length / 6.0 * dr.cross(f1 - f0);
    f0 = f1;
    m0 = m1;
  }
  return load;
}

void tower_drag_nodal(const Params& params, const Vec3& tower_axis, std::span<const Vec3> velocity_m_s, std::span<const Vec3> inflow_m_s, std::span<Vec3> force_N) {
  const std::size_t n = params.tower.size();
  for (std::size_t i = 0; i < n; ++i) force_N[i].setZero();
  if (n < 2) return;
  Vec3 f0 = drag_per_length(params, tower_axis, velocity_m_s[0], inflow_m_s[0], 0);
  for (std::size_t i = 1; i < n; ++i) {
    const Vec3 f1 = drag_per_length(params, tower_axis, velocity_m_s[i], inflow_m_s[i], i);
    const double length = params.tower[i].elevation_m - params.tower[i - 1].elevation_m;
    force_N[i - 1] += length / 6.0 * (2.0 * f0 + f1);
    force_N[i] += length / 6.0 * (f0 + 2.0 * f1);
    f0 = f1;
  }
}

}  // namespace fowtsim::aero
