// Free rigid multibody (no gravity, no damping, no external loads) with a spinning rotor:
// energy and angular momentum are invariants of the exact solution; and the gyroscopic
// precession of a spinning rotor on a pitching base against the linearised gyrostat solution.
#include <cmath>
#include <numbers>

#include <catch2/catch.hpp>

#include "fowtsim/core/rotation.hpp"
#include "fowtsim/multibody/multibody.hpp"
#include "fowtsim/multibody/oc3.hpp"
#include "test_support.hpp"

using namespace fowtsim;
using namespace fowtsim::multibody;
using fowtsim::multibody::testing::FreeProvider;
using fowtsim::multibody::testing::LambdaProvider;

namespace {

struct Drift {
  double energy = 0.0, angular = 0.0, linear = 0.0;
};

// Integrates the free OC3 system for `revolutions` rotor revolutions at `rpm` and returns the
// largest relative drift of E, |H − H0|/|H0| and |P − P0|/|P0| seen at the end of every large step.
Drift free_run(double rpm, double revolutions, double dt, Vec3 angles_deg = Vec3::Zero()) {
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
  FreeProvider provider;
  const Invariants i0 = invariants(model, s, false);
  const double e0 = i0.kinetic_energy_J + i0.potential_energy_J;
  const double duration = revolutions * 60.0 / std::abs(rpm);
  const int steps = static_cast<int>(std::ceil(duration / dt));
  Drift d;
  for (int n = 0; n < steps; ++n) {
    Multibody::advance(model, provider, n * dt, dt, s);
    const Invariants i = invariants(model, s, false);
    d.energy = std::max(d.energy, std::abs(i.kinetic_energy_J + i.potential_energy_J - e0) / e0);
    d.angular = std::max(d.angular, (i.angular_momentum_N_m_s - i0.angular_momentum_N_m_s).norm() /
                                        i0.angular_momentum_N_m_s.norm());
    d.linear = std::max(d.linear, (i.linear_momentum_N_s - i0.linear_momentum_N_s).norm() /
                                      i0.linear_momentum_N_s.norm());
  }
  return d;
}

}  // namespace

TEST_CASE("free OC3 multibody conserves energy and momentum over 1000 rotor revolutions",
          "[verification][multibody][conservation]") {
  // 1000 revolutions at 12.1 rpm = 4959 s of platform tumbling + rotor spin + drivetrain torsion
  // (2.2 Hz), RK4 at the large step 0.02 s used by seed 000 §4.5.3.
  const Drift d = free_run(12.1, 1000.0, 0.02);
  WARN("12.1 rpm: energy " << d.energy << ", angular momentum " << d.angular << ", linear " << d.linear);
  CHECK(d.energy < 1e-6);   // brief: 1e-6 relative over 1000 revolutions
  CHECK(d.angular < 1e-6);  // brief: 1e-6 relative
  CHECK(d.linear < 1e-12);  // RK4 preserves linear invariants exactly: round-off only
}

TEST_CASE("reverse rotor spin and a 90° pitched platform conserve energy and momentum",
          "[verification][multibody][conservation][robustness]") {
  const Drift reverse = free_run(-12.1, 200.0, 0.02);
  // 90° platform pitch: Euler 1-2-3 gimbal lock; the quaternion attitude has none.
  const Drift locked = free_run(12.1, 200.0, 0.02, Vec3(0.0, 90.0, 0.0));
  WARN("reverse: " << reverse.energy << " " << reverse.angular << "; 90 deg: " << locked.energy << " " << locked.angular);
  CHECK(reverse.energy < 1e-6);  // same tolerances as the 1000-revolution case
  CHECK(reverse.angular < 1e-6);
  CHECK(locked.energy < 1e-6);
  CHECK(locked.angular < 1e-6);
}

namespace {

// A gyrostat whose composite inertia is diagonal about the reference point: base mass at r with
// inertia diag(I1, I2, I3), a massless rotor of polar inertia J on the x axis at the tower top.
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

}  // namespace

namespace {

struct PrecessionResult {
  double mean_rate = 0.0, mean_rate_exact = 0.0;  // yaw / t over two nutation periods [rad/s]
  double worst_rate = 0.0;                        // max |ω − ω_exact| / |M/h| over the run [-]
};

// Euler's gyrostat equations I ω̇ + ω × (I ω + h e_x) = M with M = M_y y_b, h = J Ω, linearised
// about ω = 0 (ω_x stays 0 to first order): I2 ω̇_y = M − h ω_z, I3 ω̇_z = h ω_y, so from rest
//   ω_z = (M/h)(1 − cos ω_n t),  ω_y = (I3 M ω_n / h²) sin ω_n t,  ω_n = h / √(I2 I3),
// and the yaw angle ψ = (M/h)(t − sin(ω_n t)/ω_n): mean precession rate M/h
// (e.g. Wittenburg, Dynamics of Multibody Systems, 2008, §4.3 gyrostat).
PrecessionResult precession(double rpm, double moment) {
  const Model model = make_model(gyrostat(rpm));
  LambdaProvider provider([&](double, const State& s, AppliedLoads& out) {
    out.gravity = false;
    out.platform_moment_N_m = s.orientation.toRotationMatrix().col(1) * moment;  // about y_b
  });
  const double h = 1.0e6 * rpm * std::numbers::pi / 30.0;
  const double i2 = 2.0e8, i3 = 1.0e8;
  const double wn = std::abs(h) / std::sqrt(i2 * i3);
  const double period = 2.0 * std::numbers::pi / wn;
  State s = Multibody::make_state(model);
  const double dt = 0.05;
  const int steps = static_cast<int>(std::round(2.0 * period / dt));
  PrecessionResult r;
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

}  // namespace

TEST_CASE("gyroscopic precession of a spinning rotor on a pitching base", "[verification][multibody][gyroscopic]") {
  // Ω = ±10 rad/s (h = ±1e7 N·m·s), M = 1e3 N·m: precession M/h = ±1e-4 rad/s, nutation period
  // 88.9 s. The linearisation neglects terms of relative size ~ pitch angle ~ I3 M / h² = 1e-3.
  for (const double rpm : {95.49296585513721, -95.49296585513721}) {
    const PrecessionResult small = precession(rpm, 1.0e3);
    const PrecessionResult large = precession(rpm, 1.0e4);
    WARN("rpm " << rpm << ": precession " << small.mean_rate << " rad/s vs analytic " << small.mean_rate_exact
         << ", rel " << std::abs(small.mean_rate / small.mean_rate_exact - 1) << "; rate error/(M/h) "
         << small.worst_rate << " (M = 1e3), " << large.worst_rate << " (M = 1e4)");
    // Tolerance 2e-3 = 2 × the neglected relative size I3 M / h² (the bound, not a fit).
    CHECK(small.mean_rate == Approx(small.mean_rate_exact).epsilon(2e-3));
    CHECK(small.worst_rate < 2e-3);
    CHECK(small.mean_rate * rpm > 0.0);  // the precession follows the spin direction
    // The residual is the linearisation: it grows linearly with M (×10 → ×10; ±20 % allowed).
    CHECK(large.worst_rate / small.worst_rate == Approx(10.0).epsilon(0.2));
  }
}
