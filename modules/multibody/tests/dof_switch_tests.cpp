// DOF switches of a load case (Params::dofs): held platform DOFs stay at their initial values
// under any load, a held rotor keeps its speed, a prescribed spin follows the provider while the
// platform answers the hub's inertia through the dropped rotor row's internal constraint torque.
#include <cmath>

#include <catch2/catch.hpp>

#include "fowtsim/multibody/multibody.hpp"
#include "fowtsim/multibody/oc3.hpp"

using namespace fowtsim;
using namespace fowtsim::multibody;

namespace {

// Gravity, a large platform push and a generator torque: everything that would move a free DOF.
class Pushing final : public LoadProvider {
 public:
  SpinMotion spin;
  void loads(double, const State&, AppliedLoads& out) override {
    out.platform_force_N = Vec3(1e6, 2e5, 1e7);
    out.platform_moment_N_m = Vec3(3e7, 5e7, 1e6);
    out.generator_torque_N_m = 40000.0;
    out.rotor_moment_N_m = Vec3(2e6, 0.0, 0.0);
  }
  SpinMotion rotor_spin(double t) override {
    SpinMotion s = spin;
    s.rotor_speed_rad_s += 0.1 * t;
    s.rotor_azimuth_rad += spin.rotor_speed_rad_s * t + 0.05 * t * t;
    s.rotor_acceleration_rad_s2 = 0.1;
    s.generator_speed_rad_s = s.rotor_speed_rad_s;
    s.generator_azimuth_rad = s.rotor_azimuth_rad;
    s.generator_acceleration_rad_s2 = 0.1;
    return s;
  }
};

}  // namespace

TEST_CASE("held platform DOFs and a held rotor do not move under loads", "[unit][multibody]") {
  Params p = oc3_hywind_params();
  p.initial_conditions.platform_angles_deg = Vec3(1.0, 4.0, -2.0);
  p.initial_conditions.platform_position_m = Vec3(3.0, 0.0, 0.0);
  p.initial_conditions.rotor_speed_rpm = 12.1;
  p.dofs.platform_free = {false, false, false, false, false, false};
  p.dofs.rotor = RotorSpin::held;
  const Model model = make_model(p);
  State s = Multibody::make_state(model);
  const State s0 = s;
  Pushing loads;
  for (int k = 0; k < 100; ++k) Multibody::advance(model, loads, 0.02 * k, 0.02, s);
  // Exactly: the held rows are replaced by u̇ = 0, so the integrator adds zero to them.
  CHECK((s.position_m - s0.position_m).norm() == 0.0);
  CHECK(s.orientation.coeffs() == s0.orientation.coeffs());
  CHECK(s.rotor_speed_rad_s == s0.rotor_speed_rad_s);
  CHECK(s.rotor_azimuth_rad == Approx(s0.rotor_azimuth_rad + 2.0 * s0.rotor_speed_rad_s).epsilon(1e-12));
}

TEST_CASE("one held platform DOF stays while the others move", "[unit][multibody]") {
  Params p = oc3_hywind_params();
  p.dofs.platform_free = {true, true, false, true, true, true};  // heave held
  const Model model = make_model(p);
  State s = Multibody::make_state(model);
  Pushing loads;
  for (int k = 0; k < 50; ++k) Multibody::advance(model, loads, 0.02 * k, 0.02, s);
  CHECK(s.position_m.z() == 0.0);
  CHECK(std::abs(s.position_m.x()) > 1e-3);
}

TEST_CASE("a prescribed spin is followed exactly and the platform feels the hub's spin-up", "[unit][multibody]") {
  Params p = oc3_hywind_params();
  p.rotor.flexible_blades = true;  // the hub alone spins in the multibody
  p.dofs.rotor = RotorSpin::prescribed;
  const Model model = make_model(p);
  State s = Multibody::make_state(model);
  Pushing loads;
  loads.spin.rotor_speed_rad_s = 1.2;
  for (int k = 0; k < 50; ++k) Multibody::advance(model, loads, 0.02 * k, 0.02, s);
  const SpinMotion expected = loads.rotor_spin(1.0);
  CHECK(s.rotor_speed_rad_s == expected.rotor_speed_rad_s);
  CHECK(s.rotor_azimuth_rad == expected.rotor_azimuth_rad);
  // The prescribed acceleration enters the platform rows: a platform without loads other than
  // the spin-up reacts (roll, about the shaft) instead of staying at rest.
  class SpinOnly final : public LoadProvider {
   public:
    void loads(double, const State&, AppliedLoads& out) override { out.gravity = false; }
    SpinMotion rotor_spin(double t) override { return {0.5 * t * t, t, 1.0, 0.5 * t * t, t, 1.0}; }
  } spin_only;
  State r = Multibody::make_state(model);
  for (int k = 0; k < 10; ++k) Multibody::advance(model, spin_only, 0.02 * k, 0.02, r);
  CHECK(std::abs(r.angular_velocity_rad_s.x()) > 1e-6);
}
