#include "fowtsim/multibody/blade_body.hpp"

#include "fowtsim/core/rotation.hpp"

namespace fowtsim::multibody {

FlexibleBodyMotion blade_motion(const Model& model, const State& state, const ChainKinematics& chain, int blade) {
  FlexibleBodyMotion body;
  body.origin = &chain.blade_root[blade];
  body.rotation = &chain.rotor;
  body.orientation = chain.blade_frame_orientation[blade];
  body.first_dof = kBlade + blade * kMaxBladeModes;
  body.mode_count = model.rr_blades.mode_count;
  for (int j = 0; j < body.mode_count; ++j) {
    body.q[j] = state.blade_deflection_m[blade][j];
    body.q_rate[j] = state.blade_deflection_rate_m_s[blade][j];
  }
  return body;
}

PointKinematics blade_station_point(const Model& model, const State& state, const ChainKinematics& chain, int blade,
                                    int station) {
  const BladeStation& s = model.rr_blades.stations[station];
  return flexible_body_point(blade_motion(model, state, chain, blade), Vec3(0.0, 0.0, s.span_m), s.shape);
}

PointMotion blade_station_motion(const Model& model, const State& state, const ChainKinematics& chain, int blade,
                                 int station) {
  const BladeStation& s = model.rr_blades.stations[station];
  return flexible_body_point_motion(blade_motion(model, state, chain, blade), Vec3(0.0, 0.0, s.span_m), s.shape);
}

Vec3 blade_rotation_shape(const BladeStation& station, int mode) {
  return Vec3(-station.slope[mode].y(), station.slope[mode].x(), 0.0);
}

Mat3 blade_section_orientation(const Model& model, const State& state, const ChainKinematics& chain, int blade,
                               int station) {
  Vec3 theta = Vec3::Zero();
  for (int j = 0; j < model.rr_blades.mode_count; ++j)
    theta += state.blade_deflection_m[blade][j] * blade_rotation_shape(model.rr_blades.stations[station], j);
  return chain.blade_frame_orientation[blade] * rotation_x(theta.x()) * rotation_y(theta.y());
}

Vec3 blade_deflection(const Model& model, const State& state, int blade, int station) {
  Vec3 d = Vec3::Zero();
  for (int j = 0; j < model.rr_blades.mode_count; ++j)
    d += state.blade_deflection_m[blade][j] * model.rr_blades.stations[station].shape[j];
  return d;
}

}  // namespace fowtsim::multibody
