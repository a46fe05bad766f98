#pragma once
// The applied-loads interface between the multibody and everything that pushes on it (hydro,
// mooring, controller, blades/aero). The driver implements LoadProvider; advance() calls it at
// every Runge–Kutta stage with the stage time and stage state, so pose- and velocity-dependent
// loads (hydrostatics, Morison drag, mooring) are consistent with the integration; loads the
// driver holds over a large step (averaged blade root loads, generator torque) are simply returned
// unchanged at every stage.
#include <array>

#include "fowtsim/core/interface.hpp"
#include "fowtsim/core/types.hpp"
#include "fowtsim/multibody/model.hpp"
#include "fowtsim/multibody/state.hpp"

namespace fowtsim::multibody {

// A force on the tower at a height above the tower base along its undeflected axis.
struct TowerPointLoad {
  double height_m = 0.0;                     // above the tower base [m]
  Vec3 force_N = Vec3::Zero();               // g [N]
};
inline constexpr int kMaxTowerLoads = 64;    // capacity of AppliedLoads::tower_loads (checked at deck time)

// A load at a station of a Rayleigh–Ritz blade (model.hpp BladeStation): force at the deflected
// station and a moment, both g. Not zeroed on construction: only the first
// AppliedLoads::blade_station_load_count of each blade are read.
struct BladeStationLoad {
  Vec3 force_N;                              // g [N]
  Vec3 moment_N_m;                           // g [N·m]
};

// Everything that acts on the structure at one instant. Forces in g [N]; moments in g [N·m].
struct AppliedLoads {
  Vec3 platform_force_N = Vec3::Zero();      // on the base body (hydro + mooring + …), g [N]
  Vec3 platform_moment_N_m = Vec3::Zero();   // about the platform reference point r, g [N·m]
  // Added mass about r in g, acting as [F; M] = −A [a_r; α] (a_r, α in g); goes to the left-hand
  // side. Must be symmetric positive semi-definite (hydro's Output::added_mass).
  Mat6 platform_added_mass = Mat6::Zero();   // [kg, kg·m, kg·m²]
  double generator_torque_N_m = 0.0;         // HSS electrical torque (OpenFAST GenTq sign: > 0 brakes ψ̇ > 0) [N·m]
  // A brake holding the drivetrain at rest (stick): the generator's DOF (the rotor's with a rigid
  // shaft) gets no acceleration; the torque that takes is Evaluation::drivetrain_lock_torque_N_m.
  bool drivetrain_locked = false;
  // Flexible blades: load of blade i on the hub at its root (force; moment about point_m; both g).
  // It carries the blade's weight, inertia and gyroscopic effect. Must stay zero with rigid blades.
  std::array<RootLoads, kMaxBlades> blade_root{};
  // Resultant aerodynamic (or any external) load on the rotor body: force at the rotor apex and
  // moment about the apex, g. With rigid blades the driver sums its blade-node loads here.
  Vec3 rotor_force_N = Vec3::Zero();         // [N]
  Vec3 rotor_moment_N_m = Vec3::Zero();      // about the apex [N·m]
  // Apparent mass of what hangs on the shaft, about the apex in g, acting as
  // [F; M_apex] = −A [a_apex; α_s] (α_s the non-rotating shaft frame's angular acceleration: the
  // spin is the fast side's); goes to the left-hand side. MBBT blades hand their dynamic stiffness
  // at the root in here (the interface Jacobian, driver scenes/turbine_blades.hpp). Symmetric
  // positive semi-definite.
  Mat6 rotor_added_mass = Mat6::Zero();      // [kg, kg·m, kg·m²]
  // External point loads on the tower (its aerodynamic drag as consistent nodal loads), the first
  // tower_load_count: each acts at the tower point tower_point() places at its height, so on a
  // flexible tower it does work on the bending modes and moves with the deflection. A load below the
  // tower base (h < 0) acts on the base body; TwrBs* carry every load, a gauge those at or above it
  // (a load below the base counting as at the base).
  std::array<TowerPointLoad, kMaxTowerLoads> tower_loads{};
  int tower_load_count = 0;
  // Rayleigh–Ritz blades: loads at the first blade_station_load_count stations of each blade (the
  // aerodynamic nodes' loads, lumped there), through the deflected station's Jacobian onto the chain
  // and the blade modes.
  std::array<std::array<BladeStationLoad, kMaxBladeStations>, kMaxBlades> blade_station_loads;
  int blade_station_load_count = 0;
  bool gravity = true;                       // weight of every body, Params::gravity_m_s2 along −z_g
};

// Prescribed nacelle yaw motion (used only with NacelleParams::yaw_prescribed).
struct YawMotion {
  double angle_rad = 0.0;                    // yaw of n about z_b [rad]
  double rate_rad_s = 0.0;                   // its first time derivative [rad/s]
  double acceleration_rad_s2 = 0.0;          // its second time derivative [rad/s²]
};

// Prescribed rotor spin (used only with RotorSpin::prescribed); the generator entries are the
// LSS-equivalent θ_g and its rates, equal to the rotor's with a rigid shaft.
struct SpinMotion {
  double rotor_azimuth_rad = 0.0, rotor_speed_rad_s = 0.0, rotor_acceleration_rad_s2 = 0.0;
  double generator_azimuth_rad = 0.0, generator_speed_rad_s = 0.0, generator_acceleration_rad_s2 = 0.0;
};

// The state takes the spin as it is.
inline void set_spin(const SpinMotion& spin, State& s) {
  s.rotor_azimuth_rad = spin.rotor_azimuth_rad;
  s.rotor_speed_rad_s = spin.rotor_speed_rad_s;
  s.rotor_acceleration_rad_s2 = spin.rotor_acceleration_rad_s2;
  s.generator_azimuth_rad = spin.generator_azimuth_rad;
  s.generator_speed_rad_s = spin.generator_speed_rad_s;
  s.generator_acceleration_rad_s2 = spin.generator_acceleration_rad_s2;
}

// Implemented by the driver (and by tests). Called from advance() at every stage; must not
// allocate if the step is to stay allocation-free. A function may throw to abort the step.
class LoadProvider {
 public:
  virtual ~LoadProvider() = default;
  // Loads at time t for the stage state (its nacelle yaw already set from nacelle_yaw(t)).
  // `out` arrives default-constructed (all zero, gravity on; no blade station loads).
  virtual void loads(double t, const State& state, AppliedLoads& out) = 0;
  // The prescribed yaw at time t; called before loads() when the model's yaw is prescribed.
  virtual YawMotion nacelle_yaw(double /*t*/) { return {}; }
  // The prescribed spin at time t; called before loads() when the model's spin is prescribed.
  virtual SpinMotion rotor_spin(double /*t*/) { return {}; }
};

}  // namespace fowtsim::multibody
