// Flexible tower (issue 24): tower fore-aft / side-side Rayleigh–Ritz modes as DOFs of the multibody.
// Checks against flexbody's isolated-tower model and closed forms; every tolerance has its reason.
#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/flexbody/axial_force.hpp"
#include "fowtsim/flexbody/integrals.hpp"
#include "fowtsim/flexbody/quadrature.hpp"
#include "fowtsim/flexbody/shape_functions.hpp"
#include "fowtsim/multibody/multibody.hpp"
#include "fowtsim/multibody/oc3.hpp"
#include "fowtsim/multibody/tower_body.hpp"

using namespace fowtsim;
using namespace fowtsim::multibody;

namespace {

// Uniform tower 80 m, m 4000 kg/m, EI 4e11 N·m², on a massive platform; a point top mass at the
// tower top (nacelle CM at the top, no rotary inertia, apex at the top) so that the isolated
// tower with a top mass is the exact reference.
Params uniform_tower(double top_mass, const std::vector<std::vector<double>>& shapes) {
  Params p;
  p.platform.mass_kg = 1e7;
  p.platform.roll_inertia_kg_m2 = p.platform.pitch_inertia_kg_m2 = p.platform.yaw_inertia_kg_m2 = 1e10;
  p.tower.base_height_m = 10.0;
  p.tower.top_height_m = 90.0;
  p.tower.station_fraction = {0.0, 1.0};
  p.tower.mass_density_kg_m = {4000.0, 4000.0};
  p.tower.flexible = true;
  p.tower.fore_aft_stiffness_N_m2 = {4e11, 4e11};
  p.tower.side_side_stiffness_N_m2 = {4e11, 4e11};
  p.tower.fore_aft_mode_shapes = shapes;
  p.tower.side_side_mode_shapes = shapes;
  p.nacelle.mass_kg = top_mass;
  p.nacelle.yaw_inertia_kg_m2 = 0.0;
  p.rotor.hub_mass_kg = 0.0;
  p.rotor.hub_inertia_kg_m2 = 0.0;  // no rotary inertia at the top (the rotor row is held)
  p.rotor.tip_radius_m = 60.0;
  p.drivetrain.generator_inertia_kg_m2 = 0.0;
  p.drivetrain.gearbox_ratio = 97.0;
  p.dofs.platform_free = {false, false, false, false, false, false};
  p.dofs.rotor = RotorSpin::held;
  return p;
}

struct ZeroLoads : LoadProvider {
  bool gravity = false;
  void loads(double, const State&, AppliedLoads& out) override { out.gravity = gravity; }
};

// The tower's mass as points (mass, height above the tower base): the model's own Gauss rule on
// the station table and the yaw-bearing mass — summed point by point here, an independent check
// of the shape integrals (tower_body.hpp) that use the same points.
std::vector<std::pair<double, double>> lumped_tower(const Params& p) {
  flexbody::BeamStations table;
  const double length = p.tower.top_height_m - p.tower.base_height_m;
  for (std::size_t i = 0; i < p.tower.station_fraction.size(); ++i) {
    table.x.push_back(p.tower.station_fraction[i] * length);
    table.m.push_back(p.tower.mass_density_scale * p.tower.mass_density_kg_m[i]);
    table.EI.push_back(1.0);
  }
  std::vector<std::pair<double, double>> points;
  for (const flexbody::QuadraturePoint& q : flexbody::quadrature_points(table, {flexbody::QuadratureRule::Kind::GaussLegendre, 1, 8}))
    points.emplace_back(q.w * q.m, q.x);
  points.emplace_back(p.nacelle.yaw_bearing_mass_kg, length);
  return points;
}

// Tower coordinates (modal q, q̇) of the model: u̇ = a0 + A q + B q̇ by central differences.
struct Linear {
  Eigen::MatrixXd stiffness_part, damping_part;  // A, B
  Eigen::VectorXd offset;                        // a0
};
Linear linearise(const Model& m, const AppliedLoads& loads, const State& about) {
  const int n = m.flexible_tower.mode_count;
  auto acc = [&](const State& s) {
    Evaluation e;
    evaluate(m, s, loads, 0.0, e);
    return Eigen::VectorXd(e.acceleration.segment(kTower, n));
  };
  const State& s0 = about;
  Linear l;
  l.offset = acc(s0);
  l.stiffness_part.resize(n, n);
  l.damping_part.resize(n, n);
  const double h = 1e-4;
  for (int j = 0; j < n; ++j) {
    State a = s0, b = s0;
    a.tower_deflection_m[j] += h;
    b.tower_deflection_m[j] -= h;
    l.stiffness_part.col(j) = (acc(a) - acc(b)) / (2 * h);
    a = s0, b = s0;
    a.tower_deflection_rate_m_s[j] += h;
    b.tower_deflection_rate_m_s[j] -= h;
    l.damping_part.col(j) = (acc(a) - acc(b)) / (2 * h);
  }
  return l;
}

Eigen::VectorXd frequencies_hz(const Eigen::MatrixXd& a) {
  Eigen::EigenSolver<Eigen::MatrixXd> es(-a);
  Eigen::VectorXd w = es.eigenvalues().real().cwiseSqrt() / (2 * std::numbers::pi);
  std::sort(w.data(), w.data() + w.size());
  return w;
}

}  // namespace

TEST_CASE("rigid tower by default: no tower DOFs, the rigid channels", "[unit][multibody][flexible_tower]") {
  const Model m = make_model(oc3_hywind_params());
  CHECK(m.flexible_tower.mode_count == 0);
  CHECK(m.dof_count == 8);
  CHECK(Multibody::channels(m).size() == static_cast<std::size_t>(kChannelCount));
}

TEST_CASE("static tower-top deflection under a top force equals F L^3 / 3EI with the exact static shape",
          "[verification][multibody][flexible_tower]") {
  // One shape per plane, 1.5 x̃² − 0.5 x̃³: the exact static deflection of a uniform cantilever
  // under a tip force, so Rayleigh–Ritz is exact: q = F L³ / (3 EI) to rounding.
  const Model m = make_model(uniform_tower(1e3, {{1.5, -0.5, 0.0, 0.0, 0.0}}));
  REQUIRE(m.flexible_tower.mode_count == 2);
  AppliedLoads loads;
  loads.gravity = false;
  loads.rotor_force_N = Vec3(2e5, -1e5, 0.0);  // at the apex = the tower top
  const Linear l = linearise(m, loads, initial_state(m));
  const Eigen::VectorXd q = -l.stiffness_part.fullPivLu().solve(l.offset);
  const double exact = std::pow(80.0, 3) / (3.0 * 4e11);
  WARN("static FA " << q[0] << " vs " << 2e5 * exact << ", SS " << q[1] << " vs " << -1e5 * exact);
  // 1e-7: the central difference of a linear function is exact up to rounding of ~1e-16 × K / (h K),
  // amplified by M⁻¹K's conditioning (~1e6 here); the RR model itself is exact.
  CHECK(q[0] == Approx(2e5 * exact).epsilon(1e-7));
  CHECK(q[1] == Approx(-1e5 * exact).epsilon(1e-7));
  // And the equilibrium: evaluated at q the tower accelerations vanish.
  State s = initial_state(m);
  s.tower_deflection_m[0] = q[0];
  s.tower_deflection_m[1] = q[1];
  Evaluation e;
  evaluate(m, s, loads, 0.0, e);
  CHECK(std::abs(e.acceleration[kTower]) < 1e-9);
  CHECK(std::abs(e.acceleration[kTower + 1]) < 1e-9);
}

TEST_CASE("held-platform tower frequencies equal flexbody's isolated tower with top mass and gravity",
          "[verification][multibody][flexible_tower]") {
  // OC3 shapes and tower table on the uniform tower would be arbitrary; use the OC3 tower table and
  // shapes with a point top mass (350 t) at the top: the isolated RR model is then
  // (K_q + g K^T) q = ω² (M_q + M_t φ(H) φ(H)ᵀ) q, flexbody's integrals.
  Params p = uniform_tower(3.5e5, {});
  const Params oc3 = oc3_hywind_params();
  p.tower.base_height_m = oc3.tower.base_height_m;
  p.tower.top_height_m = oc3.tower.top_height_m;
  p.tower.station_fraction = oc3.tower.station_fraction;
  p.tower.mass_density_kg_m = oc3.tower.mass_density_kg_m;
  set_oc3_flexible_tower(p);
  p.tower.fore_aft_damping_percent.clear();
  p.tower.side_side_damping_percent.clear();
  const Model m = make_model(p);
  REQUIRE(m.flexible_tower.mode_count == 4);
  for (const bool gravity : {false, true}) {
    AppliedLoads loads;
    loads.gravity = gravity;
    const Linear l = linearise(m, loads, initial_state(m));
    const Eigen::VectorXd f = frequencies_hz(l.stiffness_part);

    // Reference: flexbody on the same table, per plane.
    using namespace fowtsim::flexbody;
    const double length = p.tower.top_height_m - p.tower.base_height_m;
    BeamStations b;
    for (std::size_t i = 0; i < p.tower.station_fraction.size(); ++i) {
      b.x.push_back(p.tower.station_fraction[i] * length);
      b.m.push_back(p.tower.mass_density_kg_m[i]);
      b.EI.push_back(p.tower.fore_aft_stiffness_N_m2[i]);
    }
    std::vector<double> reference;
    for (const auto* rows : {&p.tower.fore_aft_mode_shapes, &p.tower.side_side_mode_shapes}) {
      std::vector<ShapeFunction> shapes;
      for (const auto& c : *rows) shapes.push_back(polynomial_shape({c[0], c[1], c[2], c[3], c[4]}, length));
      const SampledBody body = sample(quadrature_points(b), shapes);
      Eigen::MatrixXd k = generalized_stiffness(body);
      if (gravity) {
        const AxialForce self = self_weight_axial_force(b, p.gravity_m_s2);
        const AxialForce top = top_mass_axial_force(3.5e5, p.gravity_m_s2);
        k += geometric_stiffness(body, [&](double x) { return self(x) + top(x); });
      }
      Eigen::MatrixXd mq = generalized_mass(body);
      Eigen::VectorXd tip(shapes.size());
      for (std::size_t j = 0; j < shapes.size(); ++j) tip[j] = shapes[j](length).u;
      mq += 3.5e5 * tip * tip.transpose();
      const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> g(k, mq);
      for (int j = 0; j < g.eigenvalues().size(); ++j) reference.push_back(std::sqrt(g.eigenvalues()[j]) / (2 * std::numbers::pi));
    }
    std::sort(reference.begin(), reference.end());
    for (int j = 0; j < 4; ++j) {
      WARN("gravity " << gravity << ": tower mode " << j + 1 << " " << f[j] << " Hz vs flexbody " << reference[j]
                      << " Hz, rel " << f[j] / reference[j] - 1);
      // 1e-6: central differences with h = 1e-4 m on an exactly linear system leave rounding only
      // (~1e-16 × ω² / (h ω²) ≈ 1e-12 relative in A); 1e-6 leaves room for the stations' quadrature
      // (8-point Gauss per interval, exact for these degree-13 integrands) vs flexbody's 8 × 8 rule.
      CHECK(f[j] == Approx(reference[j]).epsilon(1e-6));
    }
  }
}

TEST_CASE("free flexible-tower OC3 conserves energy without damping or gravity",
          "[verification][multibody][flexible_tower][conservation]") {
  // Tumbling platform, spinning rotor, drivetrain torsion and all four tower modes deflected and
  // moving; no loads, no gravity, no damping (tower or drivetrain): energy and angular momentum are
  // invariants of the exact solution. RK4 at steps h and h/2: the energy drift must be small and
  // fall at least 16× (4th order; measured 32×, the 5th-order energy error of RK4) — a wrong
  // Jacobian, bias or mass term would leave an O(1) drift that does not converge.
  auto drift = [](double step, double& angular) {
    Params p = oc3_hywind_params();
    set_oc3_flexible_tower(p);
    p.tower.fore_aft_damping_percent.clear();
    p.tower.side_side_damping_percent.clear();
    p.drivetrain.torsional_damping_N_m_s_rad = 0.0;  // DTTorDmp dissipates
    p.initial_conditions.rotor_speed_rpm = 12.1;
    p.initial_conditions.platform_angular_velocity_deg_s = Vec3(0.5, -1.0, 0.3);
    p.initial_conditions.platform_velocity_m_s = Vec3(0.3, 0.2, -0.1);
    p.max_step_s = step;
    const Model m = make_model(p);
    State s = initial_state(m);
    s.tower_deflection_m = {0.3, -0.02, -0.2, 0.01};
    s.tower_deflection_rate_m_s = {0.0, 0.1, 0.2, 0.0};
    ZeroLoads loads;
    const Invariants i0 = invariants(m, s, false);
    const double e0 = i0.kinetic_energy_J + i0.potential_energy_J;
    double worst = 0.0, t = 0.0;
    angular = 0.0;
    for (int k = 0; k < 1000; ++k) {  // 10 s: 4 periods of tower mode 1 (0.4 Hz), ~30 of mode 2 (3 Hz)
      Multibody::advance(m, loads, t, 0.01, s);
      t += 0.01;
      const Invariants i = invariants(m, s, false);
      worst = std::max(worst, std::abs(i.kinetic_energy_J + i.potential_energy_J - e0) / e0);
      angular = std::max(angular, (i.angular_momentum_N_m_s - i0.angular_momentum_N_m_s).norm() /
                                      i0.angular_momentum_N_m_s.norm());
    }
    return worst;
  };
  double angular_coarse = 0.0, angular_fine = 0.0;
  const double coarse = drift(0.005, angular_coarse), fine = drift(0.0025, angular_fine);
  WARN("flexible tower, free: energy drift " << coarse << " (5 ms), " << fine << " (2.5 ms), ratio " << coarse / fine
       << "; angular momentum " << angular_coarse << ", " << angular_fine);
  CHECK(coarse < 1e-5);            // RK4 truncation at ω h ≈ 0.1 on the fastest mode, measured ~1e-6
  CHECK(coarse / fine > 16.0);     // converges at (at least) 4th order
  CHECK(angular_coarse < 1e-8);    // measured ~1e-9: the momentum balance rows are exact
}

TEST_CASE("tower-base loads of the deflected OC3 tower in static equilibrium equal the weights and their arms",
          "[verification][multibody][flexible_tower]") {
  // Platform held, gravity: the nacelle's and rotor's overhang bend the tower; Newton on the tower
  // rows finds the static q. There u̇ = 0, so the tower-base load is the weight of everything above
  // and its moment about the deflected geometry's base: Σ m g and Σ (p − base) × m g (positions
  // from the chain, a calculation independent of outputs()' d'Alembert sums).
  Params p = oc3_hywind_params();
  set_oc3_flexible_tower(p);
  p.dofs.platform_free = {false, false, false, false, false, false};
  p.dofs.rotor = RotorSpin::held;
  const Model m = make_model(p);
  AppliedLoads loads;
  State s = initial_state(m);
  for (int iteration = 0; iteration < 4; ++iteration) {
    const Linear l = linearise(m, loads, s);
    const Eigen::VectorXd dq = -l.stiffness_part.fullPivLu().solve(l.offset);
    for (int j = 0; j < 4; ++j) s.tower_deflection_m[j] += dq[j];
  }
  Evaluation e;
  evaluate(m, s, loads, 0.0, e);
  CHECK(e.acceleration.norm() < 1e-10);  // equilibrium (Newton converged quadratically to round-off)
  const Output out = Multibody::outputs(m, loads, s);
  const ChainKinematics& k = e.kinematics;
  const Vec3 g(0.0, 0.0, -p.gravity_m_s2);
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
  auto add = [&](double mass, const Vec3& at) {
    force += mass * g;
    moment += (at - k.tower_base.position_m).cross(mass * g);
  };
  for (const auto& [mass, height] : lumped_tower(p)) add(mass, tower_point(m, s, k, height).position_m);
  add(m.nacelle.mass_kg, k.nacelle_cm.position_m);
  add(m.rotor.mass_kg, k.rotor_cm.position_m);
  WARN("static TTDspFA " << s.tower_deflection_m[0] + s.tower_deflection_m[1] << " m; TwrBsF " << out.tower_base_loads.head<3>().transpose()
       << " vs " << force.transpose() << "; TwrBsM " << out.tower_base_loads.tail<3>().transpose() << " vs " << moment.transpose());
  // 1e-9 relative: the same ~100 terms, summed point by point here and as shape integrals there.
  CHECK((out.tower_base_loads.head<3>() - force).norm() < 1e-9 * force.norm());
  CHECK((out.tower_base_loads.tail<3>() - moment).norm() < 1e-9 * moment.norm());
  const std::vector<ChannelInfo> names = Multibody::channels(m);
  REQUIRE(names.size() == static_cast<std::size_t>(kChannelCount + kTowerChannelCount));
  CHECK(names[kChannelCount].name == "TTDspFA");
  CHECK(out.channels[kChannelCount] == Approx(s.tower_deflection_m[0] + s.tower_deflection_m[1]).epsilon(1e-12));
  CHECK(out.channels[kChannelCount + 1] == Approx(s.tower_deflection_m[2] + s.tower_deflection_m[3]).margin(1e-15));
}

TEST_CASE("initial tower-top deflections go to the first mode of each direction", "[unit][multibody][flexible_tower]") {
  Params p = oc3_hywind_params();
  p.initial_conditions.tower_top_deflection_m = {0.25, -0.1};
  CHECK_THROWS_AS(make_model(p), InputError);  // rigid tower: the key needs the flexible one
  set_oc3_flexible_tower(p);
  const Model m = make_model(p);
  const State s = initial_state(m);
  CHECK(s.tower_deflection_m[0] == 0.25);
  CHECK(s.tower_deflection_m[1] == 0.0);
  CHECK(s.tower_deflection_m[2] == -0.1);
  CHECK(s.tower_deflection_m[3] == 0.0);
  const Output out = Multibody::outputs(m, AppliedLoads{}, s);
  CHECK(out.channels[kChannelCount] == Approx(0.25).epsilon(1e-12));       // TTDspFA (φ(H) = 1)
  CHECK(out.channels[kChannelCount + 1] == Approx(-0.1).epsilon(1e-12));   // TTDspSS
}

TEST_CASE("the tower's shape integrals equal Kane's sums over its mass points", "[unit][multibody][flexible_tower]") {
  // A moving, rotated, deflected and vibrating state: Σ m J_kᵀ J_k and Σ m J_kᵀ (g − a_bias,k) point
  // by point (tower_point's Jacobian and bias) against add_tower_mass / tower_dalembert, and the
  // d'Alembert load at an arbitrary u̇ against Σ m (g − a_k) and its moment.
  Params p = oc3_hywind_params();
  set_oc3_flexible_tower(p);
  const Model m = make_model(p);
  State s = initial_state(m);
  s.position_m = {3.0, -2.0, 0.5};
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.1, Vec3(0.3, 0.9, 0.2).normalized()));
  s.velocity_m_s = {0.7, -0.4, 0.2};
  s.angular_velocity_rad_s = {0.05, -0.08, 0.03};
  s.tower_deflection_m = {0.4, -0.05, 0.2, 0.03};
  s.tower_deflection_rate_m_s = {0.3, 0.1, -0.2, 0.05};
  ChainKinematics k;
  chain_kinematics(m, s, k);
  const Vec3 g(0.0, 0.0, -p.gravity_m_s2);
  GeneralisedVector udot;
  udot << 0.1, -0.2, 0.05, 0.01, -0.02, 0.015, 0.0, 0.0, 0.3, -0.1, 0.2, 0.4;
  GeneralisedMatrix lumped_mass = GeneralisedMatrix::Zero();
  GeneralisedVector lumped_force = GeneralisedVector::Zero();
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
  for (const auto& [mass, height] : lumped_tower(p)) {
    const PointKinematics q = tower_point(m, s, k, height);
    lumped_mass.noalias() += mass * q.jacobian.transpose() * q.jacobian;
    lumped_force.noalias() += q.jacobian.transpose() * (mass * (g - q.bias_acceleration_m_s2));
    const Vec3 f = mass * (g - acceleration(q, udot));
    force += f;
    moment += (q.position_m - k.reference.position_m).cross(f);
  }
  GeneralisedMatrix mass = GeneralisedMatrix::Zero();
  add_tower_mass(m, m.flexible_tower.inertia, s, k, mass);
  const TowerDAlembert bias = tower_dalembert(m, m.flexible_tower.inertia, s, k, GeneralisedVector::Zero(), g);
  GeneralisedVector f = k.reference.jacobian.transpose() * bias.force_N + k.base.jacobian.transpose() * bias.moment_N_m;
  for (int j = 0; j < 4; ++j) f[kTower + j] += bias.modal_N[j];
  // 1e-12 relative: ~80 terms summed in two orders (measured ≈ 1e-15).
  CHECK((mass - lumped_mass).norm() < 1e-12 * lumped_mass.norm());
  CHECK((f - lumped_force).norm() < 1e-12 * lumped_force.norm());
  const TowerDAlembert full = tower_dalembert(m, m.flexible_tower.inertia, s, k, udot, g);
  CHECK((full.force_N - force).norm() < 1e-12 * force.norm());
  CHECK((full.moment_N_m - moment).norm() < 1e-12 * moment.norm());
}
