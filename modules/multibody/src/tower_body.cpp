#include "fowtsim/multibody/tower_body.hpp"

#include <algorithm>

#include "fowtsim/core/rotation.hpp"

namespace fowtsim::multibody {

FlexibleBodyMotion tower_motion(const Model& model, const State& state, const ChainKinematics& chain) {
  FlexibleBodyMotion body;
  body.origin = &chain.reference;
  body.rotation = &chain.base;
  body.orientation = chain.base.orientation;
  body.first_dof = kTower;
  body.mode_count = model.flexible_tower.mode_count;
  for (int j = 0; j < body.mode_count; ++j) {
    body.q[j] = state.tower_deflection_m[j];
    body.q_rate[j] = state.tower_deflection_rate_m_s[j];
  }
  return body;
}

PointKinematics tower_point(const Model& model, const State& state, const ChainKinematics& chain, double height_m) {
  const FlexibleTower& tower = model.flexible_tower;
  const double on_tower = std::clamp(height_m, 0.0, model.tower_top_b.z() - model.tower_base_b.z());
  std::array<Vec3, kMaxBodyModes> shape{};
  for (int j = 0; j < tower.mode_count; ++j) shape[j] = tower.shape[j].value(on_tower) * tower.direction_b[j];
  return flexible_body_point(tower_motion(model, state, chain), model.tower_base_b + Vec3(0.0, 0.0, height_m), shape);
}

Vec3 tower_deflection(const Model& model, const State& state, double height_m) {
  const FlexibleTower& tower = model.flexible_tower;
  Vec3 d = Vec3::Zero();
  for (int j = 0; j < tower.mode_count; ++j) d += state.tower_deflection_m[j] * tower.shape[j].value(height_m) * tower.direction_b[j];
  return d;
}

Mat3 tower_section_orientation(const Model& model, const State& state, const Mat3& t_gb, double height_m) {
  const FlexibleTower& tower = model.flexible_tower;
  if (tower.mode_count == 0) return t_gb;
  double theta_x = 0.0, theta_y = 0.0;
  for (int j = 0; j < tower.mode_count; ++j) {
    const double turn = tower.shape[j].slope(height_m) * state.tower_deflection_m[j];
    if (j < tower.fore_aft_count) theta_y += turn;
    else theta_x -= turn;
  }
  return t_gb * rotation_x(theta_x) * rotation_y(theta_y);
}

double TowerModeShape::value(double height_m) const {
  const double x = height_m / length_m;
  double v = 0.0;
  for (int k = 6; k >= 2; --k) v = (v + coefficients[k - 2]) * x;  // Horner, then one more × x
  return v * x;
}

double TowerModeShape::slope(double height_m) const {
  const double x = height_m / length_m;
  double v = 0.0;
  for (int k = 6; k >= 2; --k) v = v * x + k * coefficients[k - 2];
  return v * x / length_m;
}

}  // namespace fowtsim::multibody
