#include "fowtsim/multibody/kinematics.hpp"

#include <cmath>

#include "fowtsim/core/rotation.hpp"
#include "fowtsim/multibody/tower_body.hpp"

namespace fowtsim::multibody {
namespace {

// Child body turning relative to `parent` about the unit axis e (g) at relative rate `rate`
// (and relative acceleration `rate_dot` when prescribed): ω = ω_p + rate e,
// α_bias = α_p,bias + rate_dot e + ω_p × (rate e). `column` ≥ 0 adds `ratio` · e to J_ω there
// (a DOF), otherwise the motion is prescribed.
RotationKinematics child_rotation(const RotationKinematics& parent, const Mat3& orientation,
                                  const Vec3& e, double rate, double rate_dot, int column,
                                  double ratio) {
  RotationKinematics c;
  c.orientation = orientation;
  c.angular_velocity_rad_s = parent.angular_velocity_rad_s + rate * e;
  c.bias_angular_acceleration_rad_s2 = parent.bias_angular_acceleration_rad_s2 +
                                       parent.angular_velocity_rad_s.cross(rate * e);
  c.jacobian = parent.jacobian;
  if (column >= 0) {
    c.jacobian.col(column) += ratio * e;
  } else {
    c.bias_angular_acceleration_rad_s2 += rate_dot * e;
  }
  return c;
}

}  // namespace

GeneralisedVector generalised_velocities(const Model& model, const State& state) {
  GeneralisedVector u = GeneralisedVector::Zero();
  u.segment<3>(kSurge) = state.velocity_m_s;
  u.segment<3>(kRoll) = state.angular_velocity_rad_s;
  u[kRotor] = state.rotor_speed_rad_s;
  if (model.generator_dof == kGenerator) u[kGenerator] = state.generator_speed_rad_s;
  for (int j = 0; j < model.flexible_tower.mode_count; ++j) u[kTower + j] = state.tower_deflection_rate_m_s[j];
  for (int b = 0; b < model.blade_count && model.rr_blades.mode_count > 0; ++b)
    for (int j = 0; j < kMaxBladeModes; ++j) u[kBlade + b * kMaxBladeModes + j] = state.blade_deflection_rate_m_s[b][j];
  return u;
}

PointKinematics point_on(const PointKinematics& origin, const RotationKinematics& body,
                         const Vec3& position_m) {
  const Vec3 rho = position_m - origin.position_m;
  const Vec3& w = body.angular_velocity_rad_s;
  PointKinematics p;
  p.position_m = position_m;
  p.velocity_m_s = origin.velocity_m_s + w.cross(rho);
  p.bias_acceleration_m_s2 = origin.bias_acceleration_m_s2 +
                             body.bias_angular_acceleration_rad_s2.cross(rho) + w.cross(w.cross(rho));
  p.jacobian = origin.jacobian - skew(rho) * body.jacobian;  // v_P = v_O − ρ̃ ω
  return p;
}

void chain_kinematics(const Model& model, const State& state, ChainKinematics& out) {
  const GeneralisedVector u = generalised_velocities(model, state);
  const double ratio = model.gearbox_ratio;

  // Base body: ω_g = T_gb ω_b, and α_g = T_gb ω̇_b exactly (d/dt(T ω_b) = T(ω̃ ω_b + ω̇_b)).
  RotationKinematics& b = out.base;
  b.orientation = state.orientation.normalized().toRotationMatrix();
  b.jacobian.setZero();
  b.jacobian.block<3, 3>(0, kRoll) = b.orientation;
  b.angular_velocity_rad_s = b.orientation * state.angular_velocity_rad_s;
  b.bias_angular_acceleration_rad_s2.setZero();

  PointKinematics& r = out.reference;
  r.position_m = state.position_m;
  r.velocity_m_s = state.velocity_m_s;
  r.bias_acceleration_m_s2.setZero();
  r.jacobian.setZero();
  r.jacobian.block<3, 3>(0, kSurge).setIdentity();

  const Mat3& t_gb = b.orientation;
  out.base_cm = point_on(r, b, r.position_m + t_gb * model.base.cm_m);
  out.tower_cm = point_on(r, b, r.position_m + t_gb * model.tower.cm_m);
  out.tower_base = point_on(r, b, r.position_m + t_gb * model.tower_base_b);
  const FlexibleTower& tower = model.flexible_tower;
  if (tower.mode_count == 0) {
    out.tower_top = point_on(r, b, r.position_m + t_gb * model.tower_top_b);
    out.tower_top_frame = b;
  } else {
    // Deflected top, and the top frame T_bt = R_x(θ_x) R_y(θ_y) with θ_y = Σ_FA φ'(H) q,
    // θ_x = −Σ_SS φ'(H) q: two successive relative rotations, each linear in q (no θ̈ bias).
    out.tower_top = tower_point(model, state, out, model.tower_top_b.z() - model.tower_base_b.z());
    double theta_x = 0.0, theta_y = 0.0, rate_x = 0.0, rate_y = 0.0;
    std::array<double, kMaxTowerModes> dx{}, dy{};
    for (int j = 0; j < tower.mode_count; ++j) {
      if (j < tower.fore_aft_count) dy[j] = tower.top_slope[j];
      else dx[j] = -tower.top_slope[j];
      theta_x += dx[j] * state.tower_deflection_m[j];
      theta_y += dy[j] * state.tower_deflection_m[j];
      rate_x += dx[j] * state.tower_deflection_rate_m_s[j];
      rate_y += dy[j] * state.tower_deflection_rate_m_s[j];
    }
    auto turn = [&](const RotationKinematics& parent, const Mat3& orientation, const Vec3& e, double rate,
                    const std::array<double, kMaxTowerModes>& d) {
      RotationKinematics c = child_rotation(parent, orientation, e, rate, 0.0, -1, 0.0);
      for (int j = 0; j < tower.mode_count; ++j) c.jacobian.col(kTower + j) += d[j] * e;
      return c;
    };
    const Mat3 t_g1 = t_gb * rotation_x(theta_x);
    const RotationKinematics first = turn(b, t_g1, t_gb.col(0), rate_x, dx);
    out.tower_top_frame = turn(first, t_g1 * rotation_y(theta_y), t_g1.col(1), rate_y, dy);
  }

  // Nacelle: prescribed yaw about the tower-top z axis (z_b with a rigid tower).
  const RotationKinematics& top_frame = out.tower_top_frame;
  const Mat3 t_gn = top_frame.orientation * rotation_z(state.nacelle_yaw_rad);
  out.nacelle = child_rotation(top_frame, t_gn, top_frame.orientation.col(2), state.nacelle_yaw_rate_rad_s,
                               state.nacelle_yaw_acceleration_rad_s2, -1, 0.0);
  const Vec3& top = out.tower_top.position_m;
  out.nacelle_cm = point_on(out.tower_top, out.nacelle, top + t_gn * model.nacelle.cm_m);
  out.imu = point_on(out.tower_top, out.nacelle, top + t_gn * model.imu_n);
  out.apex = point_on(out.tower_top, out.nacelle, top + t_gn * model.apex_n);

  // Shaft (fixed in the nacelle), rotor (ψ about x_s) and generator (N θ_g about x_s).
  out.shaft = out.nacelle;
  out.shaft.orientation = t_gn * model.shaft_in_nacelle;
  const Vec3 e_s = out.shaft.orientation.col(0);
  out.rotor = child_rotation(out.nacelle, out.shaft.orientation * rotation_x(state.rotor_azimuth_rad),
                             e_s, u[kRotor], 0.0, kRotor, 1.0);
  const double generator_rate = model.generator_dof == kGenerator ? u[kGenerator] : u[kRotor];
  out.generator = child_rotation(out.nacelle, out.shaft.orientation, e_s, ratio * generator_rate,
                                 0.0, model.generator_dof, ratio);

  const Mat3& t_gh = out.rotor.orientation;
  const Vec3& apex = out.apex.position_m;
  out.rotor_cm = point_on(out.apex, out.rotor, apex + t_gh * model.rotor.cm_m);
  for (int i = 0; i < model.blade_count; ++i) {
    out.blade_root[i] = point_on(out.apex, out.rotor, apex + t_gh * model.blade_root_h[i]);
    out.blade_root_orientation[i] = t_gh * model.blade_root_orientation_h[i];
    out.blade_frame_orientation[i] = out.blade_root_orientation[i] * rotation_z(-state.blade_pitch_rad[i]);
  }
}

Vec3 tower_axis_at_sea_level(const ChainKinematics& chain) {
  const Vec3 axis = chain.base.orientation.col(2);
  const Vec3& base = chain.tower_base.position_m;
  return std::abs(axis.z()) > 1e-9 ? Vec3(base - (base.z() / axis.z()) * axis) : base;
}

FrameMotion frame_motion(const PointKinematics& p, const RotationKinematics& body,
                         const Mat3& orientation, const GeneralisedVector& udot) {
  FrameMotion m;
  m.position_m = p.position_m;
  m.orientation = orientation;
  m.velocity_m_s = p.velocity_m_s;
  m.acceleration_m_s2 = acceleration(p, udot);
  // A frame fixed in the body: ω_f = T_gfᵀ ω_g and, since ω_g × ω_g = 0, ω̇_f = T_gfᵀ α_g.
  m.angular_velocity_rad_s = orientation.transpose() * body.angular_velocity_rad_s;
  m.angular_acceleration_rad_s2 = orientation.transpose() * angular_acceleration(body, udot);
  return m;
}

}  // namespace fowtsim::multibody
