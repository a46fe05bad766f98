#include "fowtsim/multibody/verification.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <Eigen/Eigenvalues>

#include "fowtsim/core/rotation.hpp"
#include "fowtsim/multibody/multibody.hpp"
#include "fowtsim/multibody/oc3.hpp"

namespace fowtsim::multibody::verification {
namespace {

class FreeSystem : public LoadProvider {
 public:
  void loads(double, const State&, AppliedLoads& out) override { out.gravity = false; }
};

// A constant moment about the body's y axis, gravity off.
class PitchMoment : public LoadProvider {
 public:
  explicit PitchMoment(double moment_N_m) : moment_(moment_N_m) {}
  void loads(double, const State& s, AppliedLoads& out) override {
    out.gravity = false;
    out.platform_moment_N_m = s.orientation.toRotationMatrix().col(1) * moment_;
  }

 private:
  double moment_;
};

// Linear springs about the origin in surge, sway and heave, a heave added mass, gravity off (the
// springs act about the equilibrium; gravity would only shift it).
class HeaveSprings : public LoadProvider {
 public:
  explicit HeaveSprings(double added_mass_kg) : added_mass_(added_mass_kg) {}
  void loads(double, const State& s, AppliedLoads& out) override {
    out.gravity = false;
    out.platform_force_N = Vec3(-kSurge * s.position_m.x(), -kSurge * s.position_m.y(), -kHeave * s.position_m.z());
    out.platform_added_mass(2, 2) = added_mass_;
  }

 private:
  static constexpr double kHeave = 332941.0, kSurge = 41180.0;  // N/m
  double added_mass_;
};

// The gyrostat of gyroscopic_precession(): base mass 1e6 kg with inertia diag(3e8, 2e8, 1e8),
// a massless tower and a rotor of hub inertia 1e6 kg·m² at 20 m.
Params gyrostat(double rpm) {
  Params p;
  p.gravity_m_s2 = 9.80665;
  p.max_step_s = 0.05;
  p.platform.mass_kg = 1.0e6;
  p.platform.roll_inertia_kg_m2 = 3.0e8;
  p.platform.pitch_inertia_kg_m2 = 2.0e8;
  p.platform.yaw_inertia_kg_m2 = 1.0e8;
  p.tower.base_height_m = 0.0;
  p.tower.top_height_m = 20.0;
  p.tower.station_fraction = {0.0, 1.0};
  p.tower.mass_density_kg_m = {0.0, 0.0};
  p.rotor.hub_inertia_kg_m2 = 1.0e6;
  p.rotor.tip_radius_m = 10.0;
  p.initial_conditions.rotor_speed_rpm = rpm;
  return p;
}

// Advances `s` by `steps` steps of dt under `provider` and returns the largest drift of the invariants
// from their start: energy relative to `energy_scale`, the momenta relative to their start.
Drift drift(const Model& model, LoadProvider& provider, State& s, int steps, double dt, bool gravity, double energy_scale) {
  const Invariants start = invariants(model, s, gravity);
  const double e0 = start.kinetic_energy_J + start.potential_energy_J;
  Drift d;
  for (int n = 0; n < steps; ++n) {
    Multibody::advance(model, provider, n * dt, dt, s);
    const Invariants now = invariants(model, s, gravity);
    d.energy = std::max(d.energy, std::abs(now.kinetic_energy_J + now.potential_energy_J - e0) / energy_scale);
    d.angular = std::max(d.angular, (now.angular_momentum_N_m_s - start.angular_momentum_N_m_s).norm() /
                                        start.angular_momentum_N_m_s.norm());
    d.linear = std::max(d.linear, (now.linear_momentum_N_s - start.linear_momentum_N_s).norm() / start.linear_momentum_N_s.norm());
  }
  return d;
}

}  // namespace

Drift free_run_drift(double rpm, double revolutions, double dt, const Vec3& angles_deg) {
  Params p = oc3_hywind_params();
  p.drivetrain.torsional_damping_N_m_s_rad = 0.0;  // no dissipation
  p.max_step_s = dt;
  p.initial_conditions.rotor_speed_rpm = rpm;
  p.initial_conditions.platform_angles_deg = angles_deg;
  p.initial_conditions.platform_angular_velocity_deg_s = Vec3(0.5, 1.0, 0.3);
  p.initial_conditions.platform_velocity_m_s = Vec3(0.1, -0.05, 0.02);
  const Model model = make_model(p);
  State s = Multibody::make_state(model);
  s.generator_speed_rad_s *= 1.001;  // start with a drivetrain torsion oscillation as well
  FreeSystem provider;
  const Invariants i0 = invariants(model, s, false);
  const double duration = revolutions * 60.0 / std::abs(rpm);
  return drift(model, provider, s, static_cast<int>(std::ceil(duration / dt)), dt, false, i0.kinetic_energy_J + i0.potential_energy_J);
}

Precession gyroscopic_precession(double rpm, double moment) {
  const Model model = make_model(gyrostat(rpm));
  PitchMoment provider(moment);
  const double h = 1.0e6 * rpm * std::numbers::pi / 30.0;
  const double i2 = 2.0e8, i3 = 1.0e8;
  const double wn = std::abs(h) / std::sqrt(i2 * i3);
  const double period = 2.0 * std::numbers::pi / wn;
  State s = Multibody::make_state(model);
  const double dt = 0.05;
  const int steps = static_cast<int>(std::round(2.0 * period / dt));
  Precession r;
  for (int n = 0; n < steps; ++n) {
    Multibody::advance(model, provider, n * dt, dt, s);
    const double t = (n + 1) * dt;
    const Vec3 w_exact(0.0, i3 * moment * wn / (h * h) * std::sin(wn * t), moment / h * (1.0 - std::cos(wn * t)));
    r.worst_rate = std::max(r.worst_rate, (s.angular_velocity_rad_s - w_exact).norm() / std::abs(moment / h));
  }
  const double t_end = steps * dt;
  r.mean_rate = matrix_to_euler123(s.orientation.toRotationMatrix())[2] / t_end;
  r.mean_rate_exact = moment / h * (t_end - std::sin(wn * t_end) / wn) / t_end;
  return r;
}

double heave_free_decay_period(double added_mass_kg) {
  Params p = oc3_hywind_params();
  p.drivetrain.torsional_flexibility = false;
  p.initial_conditions.platform_position_m = Vec3(0.0, 0.0, 1.0);
  const Model model = make_model(p);
  HeaveSprings provider(added_mass_kg);
  State s = Multibody::make_state(model);
  const double dt = 0.02;
  std::vector<double> crossings;
  double z_prev = s.position_m.z();
  for (int n = 0; n < 15000 && crossings.size() < 6; ++n) {
    Multibody::advance(model, provider, n * dt, dt, s);
    const double z = s.position_m.z();
    if (z_prev < 0.0 && z >= 0.0) crossings.push_back((n + z_prev / (z_prev - z)) * dt);
    z_prev = z;
  }
  if (crossings.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

BladeRows rr_blade_rows(Params p, double rpm) {
  p.rotor.precone_deg = 0.0;
  p.nacelle.shaft_tilt_deg = 0.0;
  p.dofs.platform_free = {false, false, false, false, false, false};
  p.dofs.rotor = RotorSpin::held;
  p.initial_conditions.rotor_speed_rpm = rpm;
  const Model m = make_model(p);
  const State s0 = initial_state(m);
  AppliedLoads off;
  off.gravity = false;
  Evaluation e;
  evaluate(m, s0, off, 0.0, e);
  BladeRows out;
  out.mass_kg = e.mass.block<3, 3>(kBlade, kBlade);
  Eigen::Matrix3d stiffness;
  const double h = 1e-4;  // [m]: f is linear in q but for the inertia's O(q²) terms, which central differences cancel
  for (int c = 0; c < 3; ++c) {
    State plus = s0, minus = s0;
    plus.blade_deflection_m[0][c] += h;
    minus.blade_deflection_m[0][c] -= h;
    Evaluation ep, em;
    evaluate(m, plus, off, 0.0, ep);
    evaluate(m, minus, off, 0.0, em);
    stiffness.col(c) = -(ep.force.segment<3>(kBlade) - em.force.segment<3>(kBlade)) / (2.0 * h);
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (stiffness + stiffness.transpose()), out.mass_kg,
                                                                      Eigen::EigenvaluesOnly);
  out.frequencies_hz = eig.eigenvalues().cwiseSqrt() / (2.0 * std::numbers::pi);
  return out;
}

Drift rr_free_run_drift(Params p, double seconds, double dt_s, bool gravity) {
  for (double& d : p.tower.fore_aft_damping_percent) d = 0.0;
  for (double& d : p.tower.side_side_damping_percent) d = 0.0;
  p.rotor.rayleigh_ritz_blade->flap_damping_percent = {0.0, 0.0};
  p.rotor.rayleigh_ritz_blade->edge_damping_percent = 0.0;
  p.drivetrain.torsional_damping_N_m_s_rad = 0.0;
  p.initial_conditions.platform_angular_velocity_deg_s = {1.0, -2.0, 0.5};
  if (p.tower.flexible) p.initial_conditions.tower_top_deflection_m = {0.3, -0.1};
  const Model m = make_model(p);
  State s = initial_state(m);
  s.blade_deflection_m[0] = {1.0, 0.0, 0.2};
  s.blade_deflection_m[2] = {-0.5, 0.1, -0.3};
  s.blade_pitch_rad = {0.1, 0.0, 0.3};
  class Loads : public LoadProvider {
   public:
    explicit Loads(bool g) : gravity_(g) {}
    void loads(double, const State&, AppliedLoads& out) override { out.gravity = gravity_; }

   private:
    bool gravity_;
  } loads(gravity);
  const Invariants start = invariants(m, s, gravity);
  // The motion's energy: kinetic + strain (+ weight) above the undeflected state at rest.
  const double scale = start.kinetic_energy_J + std::abs(start.potential_energy_J - invariants(m, initial_state(m), gravity).potential_energy_J);
  return drift(m, loads, s, static_cast<int>(std::lround(seconds / dt_s)), dt_s, gravity, scale);
}

}  // namespace fowtsim::multibody::verification
