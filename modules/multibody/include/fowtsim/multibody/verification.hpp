#pragma once
// The runs behind the multibody verification checks (DESIGN.md §8 tier 2), shared by the module
// tests and `fowtsim verify multibody`: conservation of the free OC3 system, gyroscopic precession
// of a gyrostat, and the heave free-decay period on constant springs. The analytic answers are
// computed here with the runs; published values and their sources stay with the callers.
#include "fowtsim/core/types.hpp"
#include "fowtsim/multibody/params.hpp"

namespace fowtsim::multibody::verification {

struct Drift {
  double energy = 0.0;   // largest |E − E0| / E0 [-]
  double angular = 0.0;  // largest |H − H0| / |H0| [-]
  double linear = 0.0;   // largest |P − P0| / |P0| [-]
};
// Integrates the free OC3 system (no gravity, damping or external loads; platform tumbling at
// (0.5, 1.0, 0.3) °/s and drifting, drivetrain torsion started by a 0.1 % generator-speed offset)
// for `revolutions` rotor revolutions at `rpm`, RK4 at the large step dt, from platform angles
// `angles_deg`; returns the largest relative drift seen at the end of every large step.
Drift free_run_drift(double rpm, double revolutions, double dt_s, const Vec3& angles_deg = Vec3::Zero());

struct Precession {
  double mean_rate = 0.0;        // yaw / t over two nutation periods [rad/s]
  double mean_rate_exact = 0.0;  // the linearised gyrostat's (M/h)(t − sin(ω_n t)/ω_n)/t [rad/s]
  double worst_rate = 0.0;       // max |ω − ω_exact| / |M/h| over the run [-]
};
// A gyrostat whose composite inertia about the reference point is diag(3e8, 2e8, 1e8) kg·m² and a
// rotor of polar inertia 1e6 kg·m² spinning at `rpm` on the x axis, a pitch moment `moment_N_m`
// about y_b from rest, gravity off, RK4 at 0.05 s for two nutation periods. Against Euler's
// gyrostat equations linearised about ω = 0: I2 ω̇_y = M − h ω_z, I3 ω̇_z = h ω_y, h = J Ω, so
//   ω_z = (M/h)(1 − cos ω_n t),  ω_y = (I3 M ω_n / h²) sin ω_n t,  ω_n = h / √(I2 I3)
// (e.g. Wittenburg, Dynamics of Multibody Systems, 2008, §4.3 gyrostat).
Precession gyroscopic_precession(double rpm, double moment_N_m);

// Heave period [s] of the OC3 structure (rigid drivetrain) released from 1 m on linear springs
// C33 = 332,941 N/m (heave) and 41,180 N/m (surge, sway), gravity off, with heave added mass
// `added_mass_kg`, RK4 at 0.02 s: the mean spacing of the first six upward zero crossings of z(t)
// (linear interpolation). NaN when fewer than two crossings occur within 300 s.
double heave_free_decay_period(double added_mass_kg);

// Rayleigh–Ritz blades (`params` with a rayleigh_ritz_blade): blade 1's three frequencies [Hz],
// ascending, on the hub held spinning at `rpm`, platform held, precone, shaft tilt and gravity off
// — the isolated blade on a spinning hub — from the central-difference linearisation of its rows
// of the equations of motion (K from f, M from the mass matrix). Also its mass block [kg].
struct BladeRows {
  Eigen::Vector3d frequencies_hz = Eigen::Vector3d::Zero();
  Eigen::Matrix3d mass_kg = Eigen::Matrix3d::Zero();
};
BladeRows rr_blade_rows(Params params, double rpm);

// The free floating turbine of `params` (flexible tower and RR blades as the caller sets them)
// with every damping off (tower, blades, drivetrain), parked rotor free to turn, platform tumbling
// at (1, −2, 0.5) °/s, tower top deflected (0.3, −0.1) m, blades 1 and 3 deflected and pitched,
// for `seconds` at RK4 step `dt_s`: the largest energy drift relative to the motion's energy
// (kinetic + strain), and the momenta's (gravity off for those; `gravity` sets the energy run).
Drift rr_free_run_drift(Params params, double seconds, double dt_s, bool gravity);

}  // namespace fowtsim::multibody::verification
