// AppliedLoads::rotor_added_mass: an apparent mass on the shaft at the apex (the MBBT rotor's
// interface Jacobian, driver scenes/turbine_blades.hpp), on the left-hand side of Kane's equations.
#include <catch2/catch.hpp>

#include "fowtsim/multibody/multibody.hpp"
#include "fowtsim/multibody/oc3.hpp"

using namespace fowtsim;
using namespace fowtsim::multibody;

TEST_CASE("the shaft's added mass is the load −A [a_apex; α_s] at the accelerations it gives", "[unit][multibody]") {
  // The OC3 turbine on its flexible tower, the spin prescribed (as with MBBT blades), in a moving,
  // deflected, turning state with gravity. Solving with A on the left must give accelerations u̇
  // at which the same system without A, loaded by −A [a_apex(u̇); α_s(u̇)] (bias included), balances:
  // the velocity-product part of a_apex and α_s is on the right, the rest in M.
  Params p = oc3_hywind_params();
  set_oc3_flexible_tower(p);
  p.rotor.flexible_blades = true;
  p.dofs.rotor = RotorSpin::prescribed;
  const Model model = make_model(p);
  State s = Multibody::make_state(model);
  s.velocity_m_s = Vec3(0.4, -0.2, 0.1);
  s.angular_velocity_rad_s = Vec3(0.02, -0.03, 0.01);
  s.rotor_speed_rad_s = s.generator_speed_rad_s = 1.26;
  s.rotor_acceleration_rad_s2 = s.generator_acceleration_rad_s2 = 0.05;
  for (int i = 0; i < model.flexible_tower.mode_count; ++i) {
    s.tower_deflection_m[i] = 0.1 / (i + 1);
    s.tower_deflection_rate_m_s[i] = 0.05 * (i % 2 ? -1.0 : 1.0);
  }
  // A symmetric positive definite 6 × 6 of the size of the blades' apparent mass (kg, kg·m, kg·m²).
  Mat6 a = Mat6::Zero();
  a.diagonal() << 2e4, 3e4, 3e4, 1.5e5, 8e5, 8e5;
  a(1, 5) = a(5, 1) = -5e3;
  a(2, 4) = a(4, 2) = 5e3;
  AppliedLoads with;
  with.rotor_added_mass = a;
  Evaluation e;
  evaluate(model, s, with, 0.0, e);
  const Vec3 a_apex = acceleration(e.kinematics.apex, e.acceleration);
  const Vec3 alpha = angular_acceleration(e.kinematics.shaft, e.acceleration);
  Vec6 acc;
  acc << a_apex, alpha;
  const Vec6 load = -(a * acc);
  AppliedLoads explicit_load;
  explicit_load.rotor_force_N = load.head<3>();
  explicit_load.rotor_moment_N_m = load.tail<3>();
  Evaluation check;
  evaluate(model, s, explicit_load, 0.0, check);
  // Two solves of the same 21 × 21 system, entries up to ~1e10: round-off ≈ 1e-14 of the largest
  // acceleration (measured 1.1e-15 relative; the yaw-bearing load 5.8e-16); 1e-12.
  const double scale = e.acceleration.cwiseAbs().maxCoeff();
  INFO("with A: " << e.acceleration.transpose() << "\nexplicit: " << check.acceleration.transpose());
  CHECK((check.acceleration - e.acceleration).cwiseAbs().maxCoeff() < 1e-12 * scale);
  // The yaw-bearing load carries −A [a; α] like any rotor load (outputs()).
  const Output with_out = Multibody::outputs(model, with, s, 0.0);
  const Output explicit_out = Multibody::outputs(model, explicit_load, s, 0.0);
  CHECK((with_out.yaw_bearing_loads - explicit_out.yaw_bearing_loads).cwiseAbs().maxCoeff() <
        1e-12 * explicit_out.yaw_bearing_loads.cwiseAbs().maxCoeff());
}
