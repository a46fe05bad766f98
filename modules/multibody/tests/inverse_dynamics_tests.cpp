// Inverse dynamics: tower-base and yaw-bearing loads against hand calculations in static
// equilibrium under gravity and under a known uniform platform acceleration (F = m a).
#include <cmath>
#include <numbers>

#include <catch2/catch.hpp>

#include "fowtsim/multibody/multibody.hpp"
#include "fowtsim/multibody/oc3.hpp"

using namespace fowtsim;
using namespace fowtsim::multibody;

namespace {

// Hand calculation of the OC3 mass above the tower base from the deck numbers (not the module):
// tower 249,718.0 kg with CM 33.3479 m above the tower base (exact integral of the table, python),
// nacelle 240,000 kg at (1.9, 0, 1.75) from the tower top, rotor = hub 56,780 kg at the apex +
// 3 blades of 17,740 kg whose CMs sit (363,231/17,740 + 1.5) m from the apex along the axes
// coned by −2.5°, i.e. 21.975 m × sin(−2.5°) along the shaft.
struct Hand {
  const double g = 9.80665;
  const double tilt = -5.0 * std::numbers::pi / 180.0;
  const double cone = -2.5 * std::numbers::pi / 180.0;
  const double m_tower = 249718.003, z_tower = 33.34790;  // above the tower base
  const double m_nacelle = 240000.0, x_nacelle = 1.9, z_nacelle = 77.6 + 1.75;
  const double m_rotor = 56780.0 + 3 * 17740.0;
  double along_shaft() const { return 3 * 17740.0 * (363231.0 / 17740.0 + 1.5) * std::sin(cone) / m_rotor; }
  double x_rotor() const { return (-5.0191 + along_shaft()) * std::cos(tilt); }
  double z_rotor() const { return 77.6 + 1.96256 + (-5.0191 + along_shaft()) * std::sin(tilt); }
  double m_above() const { return m_tower + m_nacelle + m_rotor; }
};

// Total force (0, 0, W) through the system CM: cancels gravity exactly.
AppliedLoads balanced(const Model& model) {
  const MassSummary ms = mass_summary(model);
  AppliedLoads l;
  l.platform_force_N = Vec3(0.0, 0.0, ms.mass_kg * model.params.gravity_m_s2);
  l.platform_moment_N_m = ms.cm_b_m.cross(l.platform_force_N);
  return l;
}

}  // namespace

TEST_CASE("tower-base and yaw-bearing loads in static equilibrium equal the weight above and its arm",
          "[verification][multibody][inverse]") {
  Params p = oc3_hywind_params();
  p.drivetrain.torsional_flexibility = false;
  const Model model = make_model(p);
  const State s = Multibody::make_state(model);
  const Output out = Multibody::outputs(model, balanced(model), s);
  const Hand hand;
  // In equilibrium every acceleration vanishes (round-off of M⁻¹ f with f ~ 1e8: < 1e-9).
  CHECK(out.acceleration.norm() < 1e-9);
  auto channel = [&](const char* name) {
    const auto c = Multibody::channels(model);
    for (std::size_t i = 0; i < c.size(); ++i) if (c[i].name == name) return out.channels[i];
    FAIL("no channel " << name);
    return 0.0;
  };
  const double kn = 1e-3;
  // Hand calculation; tolerance 1e-6 relative: the hand numbers carry 6–7 digits (tower CM).
  CHECK(channel("TwrBsFzt") == Approx(-hand.m_above() * hand.g * kn).epsilon(1e-6));
  CHECK(std::abs(channel("TwrBsFxt")) < 1e-6);
  CHECK(std::abs(channel("TwrBsFyt")) < 1e-6);
  const double my = hand.g * (hand.m_nacelle * hand.x_nacelle + hand.m_rotor * hand.x_rotor()) * kn;
  CHECK(channel("TwrBsMyt") == Approx(my).epsilon(1e-6));
  CHECK(std::abs(channel("TwrBsMxt")) < 1e-6);
  CHECK(std::abs(channel("TwrBsMzt")) < 1e-6);
  CHECK(channel("YawBrFzp") == Approx(-(hand.m_nacelle + hand.m_rotor) * hand.g * kn).epsilon(1e-9));
  CHECK(channel("YawBrMyp") == Approx(my).epsilon(1e-6));  // the tower is on the axis: same arm
  WARN("static: TwrBsFzt " << channel("TwrBsFzt") << " kN (hand " << -hand.m_above() * hand.g * kn << "), TwrBsMyt "
       << channel("TwrBsMyt") << " kN-m (hand " << my << ")");
}

TEST_CASE("under a uniform platform acceleration the internal forces are F = m a", "[verification][multibody][inverse]") {
  Params p = oc3_hywind_params();
  p.drivetrain.torsional_flexibility = false;
  const Model model = make_model(p);
  const MassSummary ms = mass_summary(model);
  const State s = Multibody::make_state(model);
  // 1 MN along x through the system CM, gravity off: pure translation a = F / M_total.
  AppliedLoads l;
  l.gravity = false;
  l.platform_force_N = Vec3(1.0e6, 0.0, 0.0);
  l.platform_moment_N_m = ms.cm_b_m.cross(l.platform_force_N);
  const Output out = Multibody::outputs(model, l, s);
  const Hand hand;
  const double m_total = 7466330.0 + hand.m_above();  // hand sum of the deck masses
  const double a = 1.0e6 / m_total;
  CHECK(out.platform_acceleration_m_s2.x() == Approx(a).epsilon(1e-9));     // round-off; the masses are exact
  CHECK(out.platform_angular_acceleration_rad_s2.norm() < 1e-15);           // through the CM: no rotation
  CHECK(out.tower_base_loads[0] == Approx(-hand.m_above() * a).epsilon(1e-9));
  CHECK(out.yaw_bearing_loads[0] == Approx(-(hand.m_nacelle + hand.m_rotor) * a).epsilon(1e-9));
  // Moment about the tower base of the inertia forces −m a at heights z: M_y = −a Σ m z.
  const double my = -a * (hand.m_tower * hand.z_tower + hand.m_nacelle * hand.z_nacelle + hand.m_rotor * hand.z_rotor());
  CHECK(out.tower_base_loads[4] == Approx(my).epsilon(1e-6));  // tower CM known to 6 digits
  WARN("F=ma: a " << out.platform_acceleration_m_s2.x() << " (hand " << a << "), TwrBsFxt " << out.tower_base_loads[0]
       << " N (hand " << -hand.m_above() * a << "), TwrBsMyt " << out.tower_base_loads[4] << " (hand " << my << ")");
}

TEST_CASE("a gyroscopic yaw moment appears at the yaw bearing when a spinning rotor pitches",
          "[verification][multibody][inverse][gyroscopic]") {
  // Rotor spinning at Ω about the shaft while the platform pitches at constant rate q and no
  // acceleration: the rotor's angular momentum J Ω e_s turns at q, so the nacelle must supply
  // dH/dt = q y × J Ω e_s; the load the rotor puts on the tower top is its negative. With a flat
  // shaft (tilt 0) and the rotor on the x axis: M_z = +J Ω q (hand calculation, Euler's law).
  Params p = oc3_hywind_params();
  p.nacelle.shaft_tilt_deg = 0.0;
  p.drivetrain.torsional_flexibility = false;
  p.drivetrain.generator_inertia_kg_m2 = 0.0;
  const Model model = make_model(p);
  State s = Multibody::make_state(model);
  s.rotor_speed_rad_s = 1.2671;
  s.angular_velocity_rad_s = Vec3(0.0, 0.01, 0.0);
  Evaluation eval;
  AppliedLoads l;
  l.gravity = false;
  evaluate(model, s, l, 0.0, eval);
  const RotationKinematics& r = eval.kinematics.rotor;
  const Mat3 inertia = r.orientation * model.rotor.inertia_kg_m2 * r.orientation.transpose();
  const Vec3 gyro = -(inertia * r.bias_angular_acceleration_rad_s2 + r.angular_velocity_rad_s.cross(inertia * r.angular_velocity_rad_s));
  const double j = model.rotor.inertia_kg_m2(0, 0);
  // The inertia moment of the rotor at u̇ = 0 (what the yaw bearing must react): the transverse-
  // inertia parts of I α_bias and ω × I ω cancel exactly for an axisymmetric rotor, leaving J Ω q
  // about z. Tolerance: round-off.
  CHECK(gyro.z() == Approx(j * 1.2671 * 0.01).epsilon(1e-12));
  CHECK(std::abs(gyro.x()) + std::abs(gyro.y()) < 1e-9 * std::abs(gyro.z()));
  WARN("gyroscopic yaw moment " << gyro.z() << " N m vs J Omega q " << j * 1.2671 * 0.01);
}

TEST_CASE("flexible-blade mode with rigid-blade root loads reproduces the rigid-blade tower loads",
          "[verification][multibody][inverse]") {
  // Blades as root loads: a parked rotor, each blade's weight m g at its CM handed in as a root
  // force and moment (what a beam solver returns in static equilibrium). The tower-base and
  // yaw-bearing loads must equal those of the rigid-blade model (same physics, two code paths).
  Params rigid_p = oc3_hywind_params();
  rigid_p.drivetrain.torsional_flexibility = false;
  rigid_p.initial_conditions.azimuth_deg = 17.0;
  Params flex_p = rigid_p;
  flex_p.rotor.flexible_blades = true;
  const Model rigid = make_model(rigid_p), flex = make_model(flex_p);
  const State s = Multibody::make_state(rigid);
  ChainKinematics k;
  chain_kinematics(flex, s, k);
  AppliedLoads flex_loads = balanced(rigid);  // the whole weight, blades included, held up
  const double cm_from_root = 363231.0 / 17740.0;
  for (int i = 0; i < 3; ++i) {
    RootLoads& root = flex_loads.blade_root[i];
    root.point_m = k.blade_root[i].position_m;
    root.force_N = Vec3(0.0, 0.0, -17740.0 * 9.80665);
    const Vec3 arm = cm_from_root * k.blade_root_orientation[i].col(2);
    root.moment_N_m = arm.cross(root.force_N);
  }
  const Output a = Multibody::outputs(rigid, balanced(rigid), s);
  const Output b = Multibody::outputs(flex, flex_loads, s);
  // Round-off of sums of ~1e7 N·m terms: 1e-9 relative.
  CHECK((a.tower_base_loads - b.tower_base_loads).norm() < 1e-9 * a.tower_base_loads.norm());
  CHECK((a.yaw_bearing_loads - b.yaw_bearing_loads).norm() < 1e-9 * a.yaw_bearing_loads.norm());
  CHECK(b.acceleration.norm() < 1e-9);
}

// Intent: a load on the tower (its aerodynamic drag) moves the structure exactly as the same load
// on the platform does (the rigid tower is part of the base body), and the tower-base loads carry
// it, since it acts above the tower base; the yaw bearing does not.
TEST_CASE("a tower load moves the base body as a platform load and appears in the tower-base loads",
          "[unit][multibody][inverse]") {
  const Model model = make_model(oc3_hywind_params());
  State s = Multibody::make_state(model);
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.07, Vec3::UnitY()));  // a pitched platform
  s.velocity_m_s = Vec3(0.3, 0.0, -0.1);
  AppliedLoads on_tower, on_platform;
  on_tower.tower_loads[0] = {10.0, Vec3(3.0e4, -2.0e3, 500.0)};
  on_tower.tower_loads[1] = {60.0, Vec3(1.0e4, -1.0e3, 0.0)};
  on_tower.tower_load_count = 2;
  ChainKinematics k;
  chain_kinematics(model, s, k);
  const Vec3 axis = k.base.orientation.col(2);
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();  // about the tower base
  for (int i = 0; i < on_tower.tower_load_count; ++i) {
    force += on_tower.tower_loads[i].force_N;
    moment += (on_tower.tower_loads[i].height_m * axis).cross(on_tower.tower_loads[i].force_N);
  }
  on_platform.platform_force_N = force;
  on_platform.platform_moment_N_m = moment + (k.tower_base.position_m - k.reference.position_m).cross(force);
  const Output a = Multibody::outputs(model, on_tower, s), b = Multibody::outputs(model, on_platform, s);
  CHECK((a.acceleration - b.acceleration).norm() <= 1e-12 * b.acceleration.norm());
  const Mat3 t_gb = s.orientation.toRotationMatrix();
  Vec6 carried;
  carried << t_gb.transpose() * force, t_gb.transpose() * moment;
  // b's tower base feels the platform's acceleration only through inertia; a's also the load itself.
  CHECK((a.tower_base_loads - b.tower_base_loads - carried).norm() <= 1e-9 * carried.norm());
  CHECK((a.yaw_bearing_loads - b.yaw_bearing_loads).norm() <= 1e-9 * carried.norm());
}
