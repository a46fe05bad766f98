// Flexible tower (issue 24): tower fore-aft / side-side Rayleigh–Ritz modes as DOFs of the multibody.
// Checks against flexbody's isolated-tower model and closed forms; every tolerance has its reason.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation.hpp"
#include "fowtsim/flexbody/axial_force.hpp"
#include "fowtsim/flexbody/integrals.hpp"
#include "fowtsim/flexbody/quadrature.hpp"
#include "fowtsim/flexbody/shape_functions.hpp"
#include "fowtsim/flexbody/station_segment.hpp"
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

// The tower's station table (mass per length; EI unused here) as flexbody takes it.
flexbody::BeamStations tower_table(const Params& p) {
  flexbody::BeamStations table;
  const double length = p.tower.top_height_m - p.tower.base_height_m;
  for (std::size_t i = 0; i < p.tower.station_fraction.size(); ++i) {
    table.x.push_back(p.tower.station_fraction[i] * length);
    table.m.push_back(p.tower.mass_density_scale * p.tower.mass_density_kg_m[i]);
    table.EI.push_back(1.0);
  }
  return table;
}

// The tower's mass as points (mass, height above the tower base): the model's own Gauss rule on
// the station table and the yaw-bearing mass — summed point by point here, an independent check
// of the shape integrals (tower_body.hpp) that use the same points.
std::vector<std::pair<double, double>> lumped_tower(const Params& p) {
  const double length = p.tower.top_height_m - p.tower.base_height_m;
  std::vector<std::pair<double, double>> points;
  for (const flexbody::QuadraturePoint& q : flexbody::quadrature_points(tower_table(p), {flexbody::QuadratureRule::Kind::GaussLegendre, 1, 8}))
    points.emplace_back(q.w * q.m, q.x);
  points.emplace_back(p.nacelle.yaw_bearing_mass_kg, length);
  return points;
}

// The tower's mass above height h as points (mass, height above the tower base): another Gauss rule
// (3 panels × 5 points per interval, exact for m linear × a degree-6 shape) on the piece [h, L] of
// the station table, and the yaw-bearing mass.
std::vector<std::pair<double, double>> lumped_tower_above(const Params& p, double h) {
  const double length = p.tower.top_height_m - p.tower.base_height_m;
  std::vector<std::pair<double, double>> points;
  for (const flexbody::QuadraturePoint& q :
       flexbody::quadrature_points(flexbody::segment(tower_table(p), h, length), {flexbody::QuadratureRule::Kind::GaussLegendre, 3, 5}))
    points.emplace_back(q.w * q.m, q.x + h);
  points.emplace_back(p.nacelle.yaw_bearing_mass_kg, length);
  return points;
}

// Index of a channel by name (REQUIREs it).
std::size_t channel(const Model& m, const std::string& name) {
  const std::vector<ChannelInfo> c = Multibody::channels(m);
  for (std::size_t i = 0; i < c.size(); ++i)
    if (c[i].name == name) return i;
  FAIL("no channel " << name);
  return 0;
}
Vec3 channel3(const Model& m, const Output& out, const std::string& first) {
  const std::size_t i = channel(m, first);
  return Vec3(out.channels[i], out.channels[i + 1], out.channels[i + 2]);
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
  CHECK(Multibody::channels(m).size() == static_cast<std::size_t>(kChannelCount + 3));  // + TwrClrnc1–3 (rigid blades)
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
  // ElastoDyn's OC3 gauge: TwrGagNd 10 of TwrNodes 20 on 77.6 m, (10 − ½)·77.6/20 = 36.86 m.
  const double gauge_height = 36.86;
  p.tower.gauge_heights_m = {gauge_height};
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
  REQUIRE(names.size() == static_cast<std::size_t>(kChannelCount + kTowerChannelCount + kGaugeChannelCount + 3));
  CHECK(names[kChannelCount].name == "TTDspFA");
  CHECK(out.channels[kChannelCount] == Approx(s.tower_deflection_m[0] + s.tower_deflection_m[1]).epsilon(1e-12));
  CHECK(out.channels[kChannelCount + 1] == Approx(s.tower_deflection_m[2] + s.tower_deflection_m[3]).margin(1e-15));

  // The mid-height gauge: the weight of everything above it and its moment about the deflected gauge
  // point, point by point (another quadrature of the mass above), against TwHt1FL*/ML* turned back
  // from the local frame, which is built here from the shapes' slopes at the gauge.
  const Vec3 at = tower_point(m, s, k, gauge_height).position_m;
  Vec3 gauge_force = Vec3::Zero(), gauge_moment = Vec3::Zero();
  auto add_above = [&](double mass, const Vec3& x) {
    gauge_force += mass * g;
    gauge_moment += (x - at).cross(mass * g);
  };
  for (const auto& [mass, height] : lumped_tower_above(p, gauge_height)) add_above(mass, tower_point(m, s, k, height).position_m);
  add_above(m.nacelle.mass_kg, k.nacelle_cm.position_m);
  add_above(m.rotor.mass_kg, k.rotor_cm.position_m);
  // φ_j(h), φ_j'(h) from the deck's coefficients (normalised to φ(L) = 1), independently of TowerModeShape.
  const double length = p.tower.top_height_m - p.tower.base_height_m, x = gauge_height / length;
  const std::vector<std::vector<double>> shapes = {p.tower.fore_aft_mode_shapes[0], p.tower.fore_aft_mode_shapes[1],
                                                   p.tower.side_side_mode_shapes[0], p.tower.side_side_mode_shapes[1]};
  double theta_x = 0.0, theta_y = 0.0, fore_aft = 0.0, side_side = 0.0;
  for (int j = 0; j < 4; ++j) {
    double sum = 0.0, value = 0.0, slope = 0.0;
    for (int c = 0; c < 5; ++c) {
      sum += shapes[j][c];
      value += shapes[j][c] * std::pow(x, c + 2);
      slope += (c + 2) * shapes[j][c] * std::pow(x, c + 1) / length;
    }
    const double q = s.tower_deflection_m[j];
    (j < 2 ? fore_aft : side_side) += q * value / sum;
    (j < 2 ? theta_y : theta_x) += (j < 2 ? 1.0 : -1.0) * q * slope / sum;
  }
  const Mat3 t_gt = k.base.orientation * rotation_x(theta_x) * rotation_y(theta_y);
  const Vec3 force_t = 1e3 * channel3(m, out, "TwHt1FLxt"), moment_t = 1e3 * channel3(m, out, "TwHt1MLxt");
  WARN("gauge at " << gauge_height << " m: TwHt1FL " << force_t.transpose() << " N, TwHt1ML " << moment_t.transpose()
       << " N m; rel. error F " << (t_gt * force_t - gauge_force).norm() / gauge_force.norm() << ", M "
       << (t_gt * moment_t - gauge_moment).norm() / gauge_moment.norm() << "; TwHt1TDxt "
       << out.channels[channel(m, "TwHt1TDxt")] << " vs " << fore_aft);
  // 1e-12 relative: ~60 terms by points here, shape integrals there, each rounding ~1e-16 of its term;
  // the nacelle and rotor terms, equal in both, dominate (measured 3e-20 on F, 2e-35 on M).
  CHECK((t_gt * force_t - gauge_force).norm() < 1e-12 * gauge_force.norm());
  CHECK((t_gt * moment_t - gauge_moment).norm() < 1e-12 * gauge_moment.norm());
  // TD = Σ q_j φ_j(h) per direction: one polynomial each way, 1e-12 relative (roundings of x^6).
  CHECK(out.channels[channel(m, "TwHt1TDxt")] == Approx(fore_aft).epsilon(1e-12));
  CHECK(out.channels[channel(m, "TwHt1TDyt")] == Approx(side_side).epsilon(1e-12).margin(1e-15));
}

// Loads for the gauge and point-load checks: tower loads along the tower (one below the base, as a
// heaving platform puts the lowest aero station), a rotor load and a blade-root load.
AppliedLoads tower_test_loads() {
  AppliedLoads loads;
  loads.tower_loads[0] = {-0.3, Vec3(2.0e3, 500.0, 40.0)};
  loads.tower_loads[1] = {12.0, Vec3(6.0e3, -1.0e3, 0.0)};
  loads.tower_loads[2] = {40.0, Vec3(5.0e3, 2.0e3, -100.0)};
  loads.tower_loads[3] = {77.6, Vec3(1.5e3, -800.0, 20.0)};
  loads.tower_load_count = 4;
  loads.rotor_force_N = Vec3(7.0e5, 3.0e4, -2.0e4);
  loads.rotor_moment_N_m = Vec3(4.0e6, -6.0e5, 3.0e5);
  return loads;
}

// A moving, rotated, deflected, vibrating state.
State moving_state(const Model& m) {
  State s = initial_state(m);
  s.position_m = {3.0, -2.0, 0.5};
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.1, Vec3(0.3, 0.9, 0.2).normalized()));
  s.velocity_m_s = {0.7, -0.4, 0.2};
  s.angular_velocity_rad_s = {0.05, -0.08, 0.03};
  s.rotor_speed_rad_s = 1.2;
  s.generator_speed_rad_s = 1.2;
  if (m.flexible_tower.mode_count > 0) {
    s.tower_deflection_m = {0.4, -0.05, 0.2, 0.03};
    s.tower_deflection_rate_m_s = {0.3, 0.1, -0.2, 0.05};
  }
  return s;
}

// Intent: a gauge at the tower base is the tower-base load (ElastoDyn's TwHt at the base is TwrBs),
// computed another way: the mass above as its own shape integrals (flexbody::segment from 0), the
// tower loads filtered by height; and a gauge carries exactly the tower loads at or above it.
// Flexible and rigid tower (the rigid tower's gauges are ElastoDyn's with the tower DOFs off).
TEST_CASE("a tower gauge at the base equals TwrBs*, and a gauge carries the tower loads above it",
          "[unit][multibody][flexible_tower]") {
  for (const bool flexible : {true, false}) {
    Params p = oc3_hywind_params();
    if (flexible) set_oc3_flexible_tower(p);
    p.tower.gauge_heights_m = {0.0, 40.0};
    const Model m = make_model(p);
    const State s = moving_state(m);
    const AppliedLoads loads = tower_test_loads();
    const Output out = Multibody::outputs(m, loads, s);
    Vec6 gauge;
    gauge << channel3(m, out, "TwHt1FLxt"), channel3(m, out, "TwHt1MLxt");
    Vec6 base;
    base << channel3(m, out, "TwrBsFxt"), channel3(m, out, "TwrBsMxt");
    WARN((flexible ? "flexible" : "rigid") << " tower: TwHt1 at 0 m vs TwrBs, rel. " << (gauge - base).norm() / base.norm());
    // Round-off: the same integrals from the same Gauss points (flexible), or the rigid tower's exact
    // line moments (rigid), summed in another order (measured 3.5e-16 both); 1e-14 relative.
    CHECK((gauge - base).norm() < 1e-14 * base.norm());
  }
  // The load filter: every DOF held (rigid tower, platform and rotor held), so the loads move nothing
  // and the gauge at 40 m differs by exactly the tower loads at 40 and 77.6 m and their moments about
  // the gauge point (in frame t = b).
  Params p = oc3_hywind_params();
  p.tower.gauge_heights_m = {0.0, 40.0};
  p.dofs.platform_free = {false, false, false, false, false, false};
  p.dofs.rotor = RotorSpin::held;
  const Model m = make_model(p);
  const State s = moving_state(m);
  const AppliedLoads with = tower_test_loads();
  AppliedLoads without = with;
  without.tower_load_count = 0;
  const Output a = Multibody::outputs(m, with, s), b = Multibody::outputs(m, without, s);
  ChainKinematics k;
  chain_kinematics(m, s, k);
  const Vec3 at = tower_point(m, s, k, 40.0).position_m;
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
  for (int i : {2, 3}) {
    force += with.tower_loads[i].force_N;
    moment += (tower_point(m, s, k, with.tower_loads[i].height_m).position_m - at).cross(with.tower_loads[i].force_N);
  }
  const Mat3 t_gb = k.base.orientation;
  // Differences of loads of ~1e7 N·m for increments of ~1e5: 1e-9 relative to the increment.
  CHECK((1e3 * (channel3(m, a, "TwHt2FLxt") - channel3(m, b, "TwHt2FLxt")) - t_gb.transpose() * force).norm() < 1e-9 * force.norm());
  CHECK((1e3 * (channel3(m, a, "TwHt2MLxt") - channel3(m, b, "TwHt2MLxt")) - t_gb.transpose() * moment).norm() <
        1e-9 * moment.norm());
}

// Intent: a tower point load does work on the bending modes, Q_j = F · φ_j(h) T_gb d_j (Kane's
// generalised force by hand), and on the base body as a force at its point; on the rigid tower the
// point loads give the generalised forces of their resultant and moment at the tower base, as the
// drag's resultant was applied before it was distributed.
TEST_CASE("tower point loads: modal generalised forces by hand, and the rigid tower's resultant at the base",
          "[unit][multibody][flexible_tower]") {
  for (const bool flexible : {true, false}) {
    Params p = oc3_hywind_params();
    if (flexible) set_oc3_flexible_tower(p);
    const Model m = make_model(p);
    const State s = moving_state(m);
    AppliedLoads with = tower_test_loads(), without = with;
    without.tower_load_count = 0;
    Evaluation a, b;
    evaluate(m, s, with, 0.0, a);
    evaluate(m, s, without, 0.0, b);
    const GeneralisedVector df = a.force - b.force;
    const ChainKinematics& k = a.kinematics;
    const Mat3& t_gb = k.base.orientation;
    Vec3 force = Vec3::Zero(), moment = Vec3::Zero();  // about the tower base
    GeneralisedVector expected = GeneralisedVector::Zero();
    for (int i = 0; i < with.tower_load_count; ++i) {
      const TowerPointLoad& load = with.tower_loads[i];
      const double h = std::clamp(load.height_m, 0.0, 77.6);  // the shapes end at the tower's ends
      Vec3 at = k.reference.position_m + t_gb * (m.tower_base_b + Vec3(0.0, 0.0, load.height_m));
      for (int j = 0; j < m.flexible_tower.mode_count; ++j) {
        const Vec3 d = t_gb * m.flexible_tower.direction_b[j];
        at += s.tower_deflection_m[j] * m.flexible_tower.shape[j].value(h) * d;
        expected[kTower + j] += load.force_N.dot(m.flexible_tower.shape[j].value(h) * d);
      }
      force += load.force_N;
      moment += (at - k.tower_base.position_m).cross(load.force_N);
    }
    // Rows 0–5: the resultant at the tower base through its Jacobians (the pre-distribution form).
    expected.noalias() += k.tower_base.jacobian.transpose() * force + k.base.jacobian.transpose() * moment;
    WARN((flexible ? "flexible" : "rigid") << " tower: Δf " << df.transpose() << "; rel. error vs hand "
         << (df - expected).norm() / expected.norm());
    // A few products of 1e3–1e6 summed in two orders, and Δf a difference of two force vectors of
    // ~1e8 (the weights): measured 2.2e-13 (flexible), 2.5e-14 (rigid) relative; 2e-12.
    CHECK((df - expected).norm() < 2e-12 * expected.norm());
  }
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
  // by point (tower_point's Jacobian and bias) against add_flexible_body_mass / flexible_body_dalembert, and the
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
  GeneralisedVector udot = GeneralisedVector::Zero();
  udot.head<kBlade>() << 0.1, -0.2, 0.05, 0.01, -0.02, 0.015, 0.0, 0.0, 0.3, -0.1, 0.2, 0.4;
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
  add_flexible_body_mass(m.flexible_tower.inertia, tower_motion(m, s, k), mass);
  const FlexibleBodyDAlembert bias = flexible_body_dalembert(m.flexible_tower.inertia, tower_motion(m, s, k), GeneralisedVector::Zero(), g);
  GeneralisedVector f = k.reference.jacobian.transpose() * bias.force_N + k.base.jacobian.transpose() * bias.moment_N_m;
  for (int j = 0; j < 4; ++j) f[kTower + j] += bias.modal_N[j];
  // 1e-12 relative: ~80 terms summed in two orders (measured ≈ 1e-15).
  CHECK((mass - lumped_mass).norm() < 1e-12 * lumped_mass.norm());
  CHECK((f - lumped_force).norm() < 1e-12 * lumped_force.norm());
  const FlexibleBodyDAlembert full = flexible_body_dalembert(m.flexible_tower.inertia, tower_motion(m, s, k), udot, g);
  CHECK((full.force_N - force).norm() < 1e-12 * force.norm());
  CHECK((full.moment_N_m - moment).norm() < 1e-12 * moment.norm());
}

// Intent: TwrClrnc has ElastoDyn's definition and geometry: at rest, undeflected, azimuth 0 (blade 1
// up: its distance from the yaw bearing; blades 2 and 3 below it: their distance from the yaw axis)
// the OpenFAST v5 OC3 run (5MW_OC3Spar_DLL_WTurb_WavesIrr_600s.out, first row, all deflections 0)
// gives 65.3788376 m and 55.5060730 m (twice).
TEST_CASE("TwrClrnc at rest equals OpenFAST's first row of the OC3 run", "[verification][multibody]") {
  const Model m = make_model(oc3_hywind_params());
  const Output out = Multibody::outputs(m, AppliedLoads{}, initial_state(m));
  const std::size_t i = channel(m, "TwrClrnc1");
  WARN("TwrClrnc1–3 " << out.channels[i] << ", " << out.channels[i + 1] << ", " << out.channels[i + 2]);
  // OpenFAST writes ~9 digits of a single-precision (ReKi) value: 1e-6 relative.
  CHECK(out.channels[i] == Approx(65.3788376).epsilon(1e-6));
  CHECK(out.channels[i + 1] == Approx(55.5060730).epsilon(1e-6));
  CHECK(out.channels[i + 2] == Approx(55.5060730).epsilon(1e-6));
}
