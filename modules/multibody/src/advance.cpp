// Time integration of the multibody: classical RK4 (Kutta 1901) on the first-order system
// q̇ = Q(q) u, u̇ = M⁻¹ f, with the attitude as a unit quaternion.
#include <cmath>

#include "fowtsim/core/error.hpp"
#include "fowtsim/multibody/multibody.hpp"

namespace fowtsim::multibody {
namespace {

// y = [r (3), quaternion w x y z (4), ψ, θ_g, v (3), ω_b (3), ψ̇, θ̇_g, tower q (4), q̇ (4),
// blade q (3 × 3), q̇ (3 × 3)] — 43 numbers (the flexible entries stay zero when rigid).
constexpr int kBladeCoordinates = kMaxBlades * kMaxBladeModes;
constexpr int kTowerAt = 17, kBladeAt = kTowerAt + 2 * kMaxTowerModes;
constexpr int kStateSize = kBladeAt + 2 * kBladeCoordinates;
using StateVector = Eigen::Matrix<double, kStateSize, 1>;

StateVector pack(const State& s) {
  StateVector y;
  y.segment<3>(0) = s.position_m;
  y.segment<4>(3) << s.orientation.w(), s.orientation.x(), s.orientation.y(), s.orientation.z();
  y[7] = s.rotor_azimuth_rad;
  y[8] = s.generator_azimuth_rad;
  y.segment<3>(9) = s.velocity_m_s;
  y.segment<3>(12) = s.angular_velocity_rad_s;
  y[15] = s.rotor_speed_rad_s;
  y[16] = s.generator_speed_rad_s;
  for (int j = 0; j < kMaxTowerModes; ++j) {
    y[kTowerAt + j] = s.tower_deflection_m[j];
    y[kTowerAt + kMaxTowerModes + j] = s.tower_deflection_rate_m_s[j];
  }
  for (int b = 0; b < kMaxBlades; ++b)
    for (int j = 0; j < kMaxBladeModes; ++j) {
      y[kBladeAt + b * kMaxBladeModes + j] = s.blade_deflection_m[b][j];
      y[kBladeAt + kBladeCoordinates + b * kMaxBladeModes + j] = s.blade_deflection_rate_m_s[b][j];
    }
  return y;
}

void unpack(const StateVector& y, State& s) {
  s.position_m = y.segment<3>(0);
  s.orientation = Eigen::Quaterniond(y[3], y[4], y[5], y[6]);
  s.rotor_azimuth_rad = y[7];
  s.generator_azimuth_rad = y[8];
  s.velocity_m_s = y.segment<3>(9);
  s.angular_velocity_rad_s = y.segment<3>(12);
  s.rotor_speed_rad_s = y[15];
  s.generator_speed_rad_s = y[16];
  for (int j = 0; j < kMaxTowerModes; ++j) {
    s.tower_deflection_m[j] = y[kTowerAt + j];
    s.tower_deflection_rate_m_s[j] = y[kTowerAt + kMaxTowerModes + j];
  }
  for (int b = 0; b < kMaxBlades; ++b)
    for (int j = 0; j < kMaxBladeModes; ++j) {
      s.blade_deflection_m[b][j] = y[kBladeAt + b * kMaxBladeModes + j];
      s.blade_deflection_rate_m_s[b][j] = y[kBladeAt + kBladeCoordinates + b * kMaxBladeModes + j];
    }
}

void set_yaw(const Model& model, LoadProvider& provider, double t, State& s) {
  if (model.params.nacelle.yaw_prescribed) {
    const YawMotion yaw = provider.nacelle_yaw(t);
    s.nacelle_yaw_rad = yaw.angle_rad;
    s.nacelle_yaw_rate_rad_s = yaw.rate_rad_s;
    s.nacelle_yaw_acceleration_rad_s2 = yaw.acceleration_rad_s2;
  } else {
    s.nacelle_yaw_rate_rad_s = 0.0;
    s.nacelle_yaw_acceleration_rad_s2 = 0.0;
  }
}

// A prescribed spin replaces the integrated one at every stage and at the end of the step.
void set_spin(const Model& model, LoadProvider& provider, double t, State& s) {
  if (model.params.dofs.rotor != RotorSpin::prescribed) return;
  set_spin(provider.rotor_spin(t), s);
}

// ẏ at (t, y). `scratch` carries the non-integrated parts (yaw) and receives the stage state.
StateVector derivative(const Model& model, LoadProvider& provider, double t, const StateVector& y,
                    State& scratch, Evaluation& eval) {
  unpack(y, scratch);
  scratch.orientation.normalize();
  set_yaw(model, provider, t, scratch);
  set_spin(model, provider, t, scratch);
  AppliedLoads loads;
  provider.loads(t, scratch, loads);
  evaluate(model, scratch, loads, t, eval);

  StateVector d;
  d.segment<3>(0) = scratch.velocity_m_s;
  // q̇ = ½ q ⊗ (0, ω_b): ω_b is resolved in the body frame.
  const Eigen::Quaterniond& q = scratch.orientation;
  const Vec3& w = scratch.angular_velocity_rad_s;
  d[3] = -0.5 * (q.x() * w.x() + q.y() * w.y() + q.z() * w.z());
  d.segment<3>(4) = 0.5 * (q.w() * w + q.vec().cross(w));
  d[7] = scratch.rotor_speed_rad_s;
  d.segment<3>(9) = eval.acceleration.segment<3>(kSurge);
  d.segment<3>(12) = eval.acceleration.segment<3>(kRoll);
  d[15] = eval.acceleration[kRotor];
  d.tail<kStateSize - kTowerAt>().setZero();
  for (int j = 0; j < model.flexible_tower.mode_count; ++j) {
    d[kTowerAt + j] = scratch.tower_deflection_rate_m_s[j];
    d[kTowerAt + kMaxTowerModes + j] = eval.acceleration[kTower + j];
  }
  for (int b = 0; b < model.blade_count && model.rr_blades.mode_count > 0; ++b)
    for (int j = 0; j < kMaxBladeModes; ++j) {
      d[kBladeAt + b * kMaxBladeModes + j] = scratch.blade_deflection_rate_m_s[b][j];
      d[kBladeAt + kBladeCoordinates + b * kMaxBladeModes + j] = eval.acceleration[kBlade + b * kMaxBladeModes + j];
    }
  if (model.generator_dof == kGenerator) {
    d[8] = scratch.generator_speed_rad_s;
    d[16] = eval.acceleration[kGenerator];
  } else {  // rigid shaft: the generator follows the rotor
    d[8] = d[7];
    d[16] = d[15];
  }
  return d;
}

}  // namespace

void Multibody::advance(const Model& model, LoadProvider& provider, double t, double dt, State& state) {
  if (!(dt > 0.0) || !std::isfinite(dt)) {
    throw NumericalError({"multibody", t, "dt", "pass a positive, finite time step"}, "invalid time step");
  }
  const int substeps = static_cast<int>(std::ceil(dt / model.params.max_step_s - 1e-9));
  const double h = dt / substeps;
  State scratch = state;
  Evaluation eval;
  StateVector y = pack(state);
  for (int i = 0; i < substeps; ++i) {
    const double ti = t + i * h;
    const StateVector k1 = derivative(model, provider, ti, y, scratch, eval);
    const StateVector k2 = derivative(model, provider, ti + 0.5 * h, y + 0.5 * h * k1, scratch, eval);
    const StateVector k3 = derivative(model, provider, ti + 0.5 * h, y + 0.5 * h * k2, scratch, eval);
    const StateVector k4 = derivative(model, provider, ti + h, y + h * k3, scratch, eval);
    y += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    y.segment<4>(3).normalize();
    for (int j = 0; j < kStateSize; ++j) {
      if (!std::isfinite(y[j])) {
        throw NumericalError({"multibody", ti + h, "state entry " + std::to_string(j),
                              "reduce max_step_s or dt; check the applied loads"},
                             "non-finite multibody state");
      }
    }
  }
  unpack(y, state);
  set_yaw(model, provider, t + dt, state);
  set_spin(model, provider, t + dt, state);
}

}  // namespace fowtsim::multibody
