// Rayleigh–Ritz blades on the hub (issue 24): each blade a flexible body with ElastoDyn's flap 1,
// flap 2 and edge 1 shapes. Checked against Kane's sums point by point, flexbody's isolated rotating
// blade, the rigid-blade model's mass and the invariants of the free system.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>

#include "fowtsim/core/rotation.hpp"
#include "fowtsim/flexbody/blade_deck.hpp"
#include "fowtsim/flexbody/blade_points.hpp"
#include "fowtsim/flexbody/blade_shapes.hpp"
#include "fowtsim/flexbody/rr_blade.hpp"
#include "fowtsim/multibody/blade_body.hpp"
#include "fowtsim/multibody/multibody.hpp"
#include "fowtsim/multibody/oc3.hpp"
#include "fowtsim/multibody/verification.hpp"

using namespace fowtsim;
using namespace fowtsim::multibody;

namespace {

flexbody::ElastoDynBlade nrel5mw_blade() {
  return flexbody::read_elastodyn_blade(FOWTSIM_SOURCE_DIR "/inputs/nrel5mw/blade_elastodyn.yaml");
}

// ElastoDyn's 17 blade-node midpoints (the rule the blade's integrals use) [m].
std::vector<double> node_spans(const flexbody::ElastoDynBlade& b, int nodes = 17) {
  std::vector<double> x;
  for (int j = 0; j < nodes; ++j) x.push_back((j + 0.5) * b.length() / nodes);
  return x;
}

Params oc3_with_rr_blades() {
  Params p = oc3_hywind_params();
  p.rotor.rayleigh_ritz_blade = nrel5mw_blade();
  p.rotor.blade_station_spans_m = node_spans(*p.rotor.rayleigh_ritz_blade);
  return p;
}

// The value of channel `name` in `out` (FAIL if the model has no such channel).
double channel_value(const Model& m, const Output& out, const std::string& name) {
  const auto channels = Multibody::channels(m);
  for (std::size_t j = 0; j < channels.size(); ++j)
    if (channels[j].name == name) return out.channels[j];
  FAIL("no channel " << name);
  return 0.0;
}

}  // namespace

TEST_CASE("a Rayleigh-Ritz blade's shape integrals equal Kane's sums over its mass points", "[unit][multibody][rr_blades]") {
  // A moving, pitched, deflected and vibrating state on the flexible tower: Σ m J_kᵀ J_k and the
  // d'Alembert load Σ m (g − a_k) point by point (blade_station_point at ElastoDyn's nodes, the same
  // masses as the integrals) against add_flexible_body_mass / flexible_body_dalembert.
  Params p = oc3_with_rr_blades();
  set_oc3_flexible_tower(p);
  const Model m = make_model(p);
  State s = initial_state(m);
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.1, Vec3(0.3, 0.9, 0.2).normalized()));
  s.velocity_m_s = {0.7, -0.4, 0.2};
  s.angular_velocity_rad_s = {0.05, -0.08, 0.03};
  s.rotor_azimuth_rad = 0.7;
  s.rotor_speed_rad_s = 1.3;
  s.tower_deflection_m = {0.4, -0.05, 0.2, 0.03};
  s.tower_deflection_rate_m_s = {0.3, 0.1, -0.2, 0.05};
  s.blade_pitch_rad = {0.2, 0.3, -0.1};
  s.blade_deflection_m[1] = {2.0, -0.3, 0.5};
  s.blade_deflection_rate_m_s[1] = {1.0, 0.4, -0.7};
  ChainKinematics k;
  chain_kinematics(m, s, k);
  const Vec3 g(0.0, 0.0, -p.gravity_m_s2);
  GeneralisedVector udot = GeneralisedVector::Random();
  flexbody::BladeRule rule;
  rule.kind = flexbody::BladeRule::Kind::ElastoDynNodes;
  const std::vector<flexbody::BladePoint> points = flexbody::blade_points(*p.rotor.rayleigh_ritz_blade, rule);
  GeneralisedMatrix lumped_mass = GeneralisedMatrix::Zero();
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
  std::array<double, 3> modal{};
  const int b = 1;
  const GeneralisedVector u = generalised_velocities(m, s);
  double worst_ju = 0.0;
  for (int i = 0; i < 17; ++i) {
    const double mass = points[static_cast<std::size_t>(i)].w * points[static_cast<std::size_t>(i)].m;
    const PointKinematics q = blade_station_point(m, s, k, b, i);
    worst_ju = std::max(worst_ju, (q.jacobian * u - q.velocity_m_s).norm() / q.velocity_m_s.norm());
    lumped_mass.noalias() += mass * q.jacobian.transpose() * q.jacobian;
    const Vec3 f = mass * (g - acceleration(q, udot));
    force += f;
    moment += (q.position_m - k.blade_root[b].position_m).cross(f);
    for (int j = 0; j < 3; ++j) modal[j] += q.jacobian.col(kBlade + 3 * b + j).dot(f);
  }
  GeneralisedMatrix mass = GeneralisedMatrix::Zero();
  add_flexible_body_mass(m.rr_blades.inertia, blade_motion(m, s, k, b), mass);
  const FlexibleBodyDAlembert full = flexible_body_dalembert(m.rr_blades.inertia, blade_motion(m, s, k, b), udot, g);
  WARN("J u vs v " << worst_ju);
  CHECK(worst_ju < 1e-12);  // the Jacobian is the velocity's (fixed yaw): round-off
  // 1e-12 relative: 17 terms summed in two orders (measured ≈ 1e-15).
  CHECK((mass - lumped_mass).norm() < 1e-12 * lumped_mass.norm());
  CHECK((full.force_N - force).norm() < 1e-12 * force.norm());
  CHECK((full.moment_N_m - moment).norm() < 1e-12 * moment.norm());
  for (int j = 0; j < 3; ++j) CHECK(std::abs(full.modal_N[j] - modal[j]) < 1e-12 * force.norm());
}

TEST_CASE("blade station loads enter the equations as the stations' virtual work", "[unit][multibody][rr_blades]") {
  // f(loads) − f(no loads) = Σ_s J_sᵀ F_s + J_θ,sᵀ M_s, with J_s the deflected station's Jacobian and
  // J_θ,s the section's rotation Jacobian (the hub's plus the modes' rotation shapes), point by point.
  Params p = oc3_with_rr_blades();
  set_oc3_flexible_tower(p);
  const Model m = make_model(p);
  State s = initial_state(m);
  s.rotor_azimuth_rad = 0.4;
  s.tower_deflection_m = {0.3, 0.0, -0.1, 0.0};
  s.blade_pitch_rad = {0.1, 0.5, -0.2};
  s.blade_deflection_m = {{{1.0, 0.2, -0.3}, {0.5, -0.1, 0.4}, {-0.8, 0.05, 0.1}}};
  AppliedLoads loads;
  loads.blade_station_load_count = m.rr_blades.station_count;
  GeneralisedVector expected = GeneralisedVector::Zero();
  ChainKinematics k;
  chain_kinematics(m, s, k);
  for (int b = 0; b < 3; ++b)
    for (int i = 0; i < m.rr_blades.station_count; ++i) {
      const Vec3 force(1.0e3 * (i + 1), -2.0e2 * b, 50.0 * i), moment(10.0 * b, 30.0, -5.0 * i);
      loads.blade_station_loads[b][i] = {force, moment};
      Jacobian turn = k.rotor.jacobian;
      for (int j = 0; j < 3; ++j)
        turn.col(kBlade + 3 * b + j) += k.blade_frame_orientation[b] * blade_rotation_shape(m.rr_blades.stations[i], j);
      expected += blade_station_point(m, s, k, b, i).jacobian.transpose() * force + turn.transpose() * moment;
    }
  Evaluation with, without;
  evaluate(m, s, loads, 0.0, with);
  evaluate(m, s, AppliedLoads{}, 0.0, without);
  // Sums in another order: 1e-12 of the largest entry (measured ≈ 1e-15).
  CHECK((with.force - without.force - expected).norm() < 1e-12 * expected.norm());
}

TEST_CASE("Rayleigh-Ritz blades carry the rigid blades' mass: the same rotor from their mass moments", "[unit][multibody][rr_blades]") {
  // The rigid-blade model with the RR blade's own mass and moments (ElastoDyn's 17-node rule, the
  // numbers of its summary file) must give the same composite mass, CM and inertia as the
  // undeflected RR blades.
  const Params rr = oc3_with_rr_blades();
  Params rigid = oc3_hywind_params();
  flexbody::BladeRule rule;
  rule.kind = flexbody::BladeRule::Kind::ElastoDynNodes;
  const flexbody::BladeMassProperties mp =
      flexbody::mass_properties(flexbody::sample_blade(*rr.rotor.rayleigh_ritz_blade, rule));
  rigid.rotor.blade_mass_kg = mp.mass;
  rigid.rotor.blade_first_mass_moment_kg_m = mp.first_moment;
  rigid.rotor.blade_second_mass_moment_kg_m2 = mp.second_moment;
  const MassSummary a = mass_summary(make_model(rr)), b = mass_summary(make_model(rigid));
  // Round-off of two summation orders (measured ≈ 1e-15 relative).
  CHECK(a.mass_kg == Approx(b.mass_kg).epsilon(1e-12));
  CHECK((a.cm_b_m - b.cm_b_m).norm() < 1e-12 * b.cm_b_m.norm());
  CHECK((a.inertia_ref_kg_m2 - b.inertia_ref_kg_m2).norm() < 1e-12 * b.inertia_ref_kg_m2.norm());
}

TEST_CASE("the blades on a spinning hub have flexbody's rotating-blade frequencies", "[verification][multibody][rr_blades]") {
  // Platform held, spin held at Ω, no precone, tilt or gravity (verification::rr_blade_rows): each
  // blade's rows are the isolated blade on a hub spinning at Ω, K(Ω) = K + Ω² (G − S) of
  // flexbody::rr_blade_matrices — the softening S comes here from the inertia terms ω × (ω × ρ), the
  // stiffening G from eq. 26.
  const flexbody::ElastoDynBlade blade = nrel5mw_blade();
  flexbody::BladeRule rule;
  rule.kind = flexbody::BladeRule::Kind::ElastoDynNodes;
  const flexbody::RrBladeMatrices iso = flexbody::rr_blade_matrices(blade, flexbody::sample_blade(blade, rule));
  for (const double rpm : {0.0, 12.1, 30.0}) {
    const verification::BladeRows rows = verification::rr_blade_rows(oc3_with_rr_blades(), rpm);
    const Eigen::Vector3d expected = flexbody::natural_frequencies_hz(iso, rpm * std::numbers::pi / 30.0);
    WARN("Ω " << rpm << " rpm: " << rows.frequencies_hz.transpose() << " Hz; flexbody " << expected.transpose());
    // Central differences of forces linear in q (the inertia's O(q²) terms cancel; no bias at q = 0
    // without gravity): round-off, measured 2.2e-16 at 12.1 rpm; 1e-12 for another compiler's rounding.
    for (int i = 0; i < 3; ++i) CHECK(rows.frequencies_hz[i] == Approx(expected[i]).epsilon(1e-12));
    CHECK((rows.mass_kg - iso.mass).norm() < 1e-12 * iso.mass.norm());
  }
}

TEST_CASE("the free floating turbine with Rayleigh-Ritz blades conserves energy and momentum", "[verification][multibody][rr_blades]") {
  // verification::rr_free_run_drift: no damping (tower, blades, drivetrain), no load but gravity
  // (momenta: none), parked rotor free to turn (the centrifugal stiffening Ω² G has no potential,
  // so the spin starts at zero and stays small), flexible tower, 20 s at 0.02 s.
  Params p = oc3_with_rr_blades();
  set_oc3_flexible_tower(p);
  for (const bool gravity : {true, false}) {
    const verification::Drift d = verification::rr_free_run_drift(p, 20.0, 0.02, gravity);
    WARN("gravity " << gravity << ": energy " << d.energy << " of the motion's energy, |ΔH|/|H| " << d.angular << ", |ΔP|/|P| " << d.linear);
    // RK4 truncation at 0.02 s on the blades' 1–2 Hz modes (5th order in the step: 2.6e-6 → 1.8e-9
    // from 0.02 to 0.005 s with the hub held), measured 1.8e-6: 2e-5.
    CHECK(d.energy < 2e-5);
    if (!gravity) {  // momenta: 4th-order truncation, measured 1.1e-10 and 3.4e-10: 10×
      CHECK(d.angular < 1e-9);
      CHECK(d.linear < 3e-9);
    }
  }
}

TEST_CASE("Rayleigh-Ritz blade channels: root loads are the blade's on the hub, tips the modal deflection", "[unit][multibody][rr_blades]") {
  // A deflected blade 1 with a load at its tip station: RootF/M{x,y,z}c1 are its d'Alembert load plus
  // the tip load (force; moment about the root with the deflected arm) in the coned frame c, and
  // TipD{x,y}{c,b}1 the modal deflection Σ q φ(tip) in c and in the pitched b.
  Params p = oc3_with_rr_blades();
  const Model m = make_model(p);
  State s = initial_state(m);
  s.blade_deflection_m[0] = {1.5, -0.2, 0.4};
  s.blade_pitch_rad[0] = 0.3;
  AppliedLoads loads;
  loads.blade_station_load_count = m.rr_blades.station_count;
  for (auto& blade : loads.blade_station_loads)
    for (auto& at : blade) at = {Vec3::Zero(), Vec3::Zero()};
  const int tip = m.rr_blades.station_count - 1;
  loads.blade_station_loads[0][tip] = {Vec3(2.0e4, -5.0e3, 1.0e3), Vec3(0.0, 0.0, 3.0e3)};
  const Output out = Multibody::outputs(m, loads, s);
  Evaluation e;
  evaluate(m, s, loads, 0.0, e);
  const ChainKinematics& k = e.kinematics;
  const FlexibleBodyDAlembert d =
      flexible_body_dalembert(m.rr_blades.inertia, blade_motion(m, s, k, 0), e.acceleration, Vec3(0.0, 0.0, -p.gravity_m_s2));
  const Vec3 arm = blade_station_point(m, s, k, 0, tip).position_m - k.blade_root[0].position_m;
  const Vec3 force = d.force_N + loads.blade_station_loads[0][tip].force_N;
  const Vec3 moment = d.moment_N_m + arm.cross(loads.blade_station_loads[0][tip].force_N) + loads.blade_station_loads[0][tip].moment_N_m;
  auto at = [&](const std::string& name) { return channel_value(m, out, name); };
  const Mat3& t_gc = k.blade_root_orientation[0];
  const Vec3 fc = 1e-3 * t_gc.transpose() * force, mc = 1e-3 * t_gc.transpose() * moment;
  // Same sums in another order: 1e-12 relative to the largest component.
  for (int a = 0; a < 3; ++a) {
    CHECK(std::abs(at(std::string("RootF") + "xyz"[a] + "c1") - fc[a]) < 1e-12 * fc.norm());
    CHECK(std::abs(at(std::string("RootM") + "xyz"[a] + "c1") - mc[a]) < 1e-12 * mc.norm());
  }
  const Vec3 tip_b = blade_deflection(m, s, 0, tip);
  const Vec3 tip_c = rotation_z(-0.3) * tip_b;
  CHECK(at("TipDxb1") == Approx(tip_b.x()).epsilon(1e-14));
  CHECK(at("TipDyb1") == Approx(tip_b.y()).epsilon(1e-14));
  CHECK(at("OoPDefl1") == Approx(tip_c.x()).epsilon(1e-12));
  CHECK(at("IPDefl1") == Approx(tip_c.y()).epsilon(1e-12));
  // The flap shapes are ElastoDyn's, normalised to a unit tip deflection along their own direction:
  // undeflected pitch and twist at the tip ≈ 0, so q_flap1 = 1 moves the tip ≈ 1 m out of plane.
  State unit = initial_state(m);
  unit.blade_deflection_m[0] = {1.0, 0.0, 0.0};
  const Vec3 flap1 = blade_deflection(m, unit, 0, tip);
  WARN("flap 1 at the tip per unit q: " << flap1.transpose());
  CHECK(std::abs(flap1.x() - 1.0) < 0.05);  // the tip's twist is ≈ 0 (0.106°), the twisted shape ≈ 1 along x
}


TEST_CASE("Rayleigh-Ritz blade gauges: the blade beyond, at the root the root load", "[unit][multibody][rr_blades]") {
  // Gauges at the root and at the 5th of ElastoDyn's 17 element boundaries (x/L = 5/17), a pitched,
  // deflected, vibrating blade 1 with loads at every station: Spn1 equals RootF/M{x,y,z}b1 turned by
  // the structural twist at the root (ElastoDyn's local frame n there); Spn2 equals the sum over the
  // node masses and station loads beyond 5/17 L by points (the stations are the node midpoints),
  // about the deflected gauge point, in the local section frame (slopes, twist from the deck).
  Params p = oc3_with_rr_blades();
  p.rotor.blade_gauge_fractions = {0.0, 5.0 / 17.0};
  const Model m = make_model(p);
  State s = initial_state(m);
  s.rotor_speed_rad_s = 1.2;
  s.blade_pitch_rad[0] = 0.25;
  s.blade_deflection_m[0] = {1.2, -0.1, 0.3};
  s.blade_deflection_rate_m_s[0] = {0.4, 0.2, -0.5};
  AppliedLoads loads;
  loads.blade_station_load_count = m.rr_blades.station_count;
  for (int b = 0; b < 3; ++b)
    for (int i = 0; i < m.rr_blades.station_count; ++i)
      loads.blade_station_loads[b][i] = {Vec3(2.0e3 + 100.0 * i, -300.0, 20.0 * i), Vec3(0.0, 40.0, 5.0 * i)};
  const Output out = Multibody::outputs(m, loads, s);
  auto at = [&](const std::string& name) { return channel_value(m, out, name); };
  // At the root the local frame is b turned by the structural twist there: Spn1 = R_z(θ_s) Root*b.
  const Mat3 twist = rotation_z(m.rr_blades.gauges[0].station.twist_rad);
  const Vec3 root_force = twist * Vec3(at("RootFxb1"), at("RootFyb1"), at("RootFzb1"));
  const Vec3 root_moment = twist * Vec3(at("RootMxb1"), at("RootMyb1"), at("RootMzb1"));
  for (int a = 0; a < 3; ++a) {
    // Both from the same integrals and loads in another order: round-off.
    CHECK(std::abs(at(std::string("Spn1FL") + "xyz"[a] + "b1") - root_force[a]) < 1e-12 * root_force.norm());
    CHECK(std::abs(at(std::string("Spn1ML") + "xyz"[a] + "b1") - root_moment[a]) < 1e-12 * root_moment.norm());
  }
  CHECK(m.rr_blades.gauges[0].station.twist_rad == Approx(13.308 * std::numbers::pi / 180.0).epsilon(1e-12));  // StrcTwst at the root
  Evaluation e;
  evaluate(m, s, loads, 0.0, e);
  const ChainKinematics& k = e.kinematics;
  flexbody::BladeRule rule;
  rule.kind = flexbody::BladeRule::Kind::ElastoDynNodes;
  const std::vector<flexbody::BladePoint> points = flexbody::blade_points(*p.rotor.rayleigh_ritz_blade, rule);
  const Vec3 g(0.0, 0.0, -p.gravity_m_s2);
  const BladeGauge& gauge = m.rr_blades.gauges[1];
  const Vec3 gauge_point =
      flexible_body_point_motion(blade_motion(m, s, k, 0), Vec3(0.0, 0.0, gauge.station.span_m), gauge.station.shape).position_m;
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
  for (int i = 5; i < 17; ++i) {
    const PointKinematics q = blade_station_point(m, s, k, 0, i);
    const Vec3 f = points[static_cast<std::size_t>(i)].w * points[static_cast<std::size_t>(i)].m * (g - acceleration(q, e.acceleration)) +
                   loads.blade_station_loads[0][i].force_N;
    force += f;
    moment += (q.position_m - gauge_point).cross(f) + loads.blade_station_loads[0][i].moment_N_m;
  }
  const BladeStationLoad& tip = loads.blade_station_loads[0][17];
  force += tip.force_N;
  moment += (blade_station_point(m, s, k, 0, 17).position_m - gauge_point).cross(tip.force_N) + tip.moment_N_m;
  Vec3 theta = Vec3::Zero();
  for (int j = 0; j < 3; ++j) theta += s.blade_deflection_m[0][j] * blade_rotation_shape(gauge.station, j);
  const Mat3 local = k.blade_frame_orientation[0] * rotation_x(theta.x()) * rotation_y(theta.y()) *
                     rotation_z(-flexbody::blade_twist(*p.rotor.rayleigh_ritz_blade, gauge.station.span_m));
  const Vec3 f_local = 1e-3 * local.transpose() * force, m_local = 1e-3 * local.transpose() * moment;
  WARN("gauge at 5/17 L: F " << f_local.transpose() << " kN, M " << m_local.transpose() << " kN·m");
  for (int a = 0; a < 3; ++a) {
    // ~15 terms in two orders: 1e-12 of the vector's size.
    CHECK(std::abs(at(std::string("Spn2FL") + "xyz"[a] + "b1") - f_local[a]) < 1e-12 * f_local.norm());
    CHECK(std::abs(at(std::string("Spn2ML") + "xyz"[a] + "b1") - m_local[a]) < 1e-12 * m_local.norm());
  }
}
