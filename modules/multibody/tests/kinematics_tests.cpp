// Large-angle kinematics of the chain: point velocities and accelerations, and body angular
// velocities and accelerations, equal finite differences of positions and orientations along
// random smooth trajectories of every joint coordinate (platform 6 DOF with angles up to ~80°,
// prescribed yaw, rotor and generator azimuth).
#include <cmath>
#include <random>

#include <catch2/catch.hpp>

#include "fowtsim/core/rotation.hpp"
#include "fowtsim/flexbody/blade_deck.hpp"
#include "fowtsim/multibody/blade_body.hpp"
#include "fowtsim/multibody/dynamics.hpp"
#include "fowtsim/multibody/kinematics.hpp"
#include "fowtsim/multibody/multibody.hpp"
#include "fowtsim/multibody/oc3.hpp"
#include "fowtsim/multibody/tower_body.hpp"

using namespace fowtsim;
using namespace fowtsim::multibody;

namespace {

// q_i(t) = a_i + b_i sin(c_i t + d_i) for each of the 11 joint coordinates, the 4 tower modes and
// the 9 blade modes.
constexpr int kCoordinates = 11 + kMaxTowerModes + kMaxBlades * kMaxBladeModes;
struct Trajectory {
  double a[kCoordinates], b[kCoordinates], c[kCoordinates], d[kCoordinates];
  explicit Trajectory(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < kCoordinates; ++i) {
      const bool angle = i >= 3 && i < 11;
      a[i] = angle ? 0.6 * u(rng) : 5.0 * u(rng);
      b[i] = angle ? 0.7 * u(rng) : 3.0 * u(rng);
      c[i] = 0.5 + std::abs(u(rng));   // rad/s
      d[i] = 3.0 * u(rng);
    }
  }
  double q(int i, double t) const { return a[i] + b[i] * std::sin(c[i] * t + d[i]); }
  double qd(int i, double t) const { return b[i] * c[i] * std::cos(c[i] * t + d[i]); }
  double qdd(int i, double t) const { return -b[i] * c[i] * c[i] * std::sin(c[i] * t + d[i]); }
  Vec3 angles(double t) const { return Vec3(q(3, t), q(4, t), q(5, t)); }
  Vec3 angle_rates(double t) const { return Vec3(qd(3, t), qd(4, t), qd(5, t)); }
  // ω_b = E(θ) θ̇ (core/rotation.hpp), exact.
  Vec3 omega_body(double t) const { return euler123_rate_matrix(angles(t)) * angle_rates(t); }

  State state(double t) const {
    State s;
    s.position_m = Vec3(q(0, t), q(1, t), q(2, t));
    s.orientation = Eigen::Quaterniond(euler123_to_matrix(angles(t)));
    s.velocity_m_s = Vec3(qd(0, t), qd(1, t), qd(2, t));
    s.angular_velocity_rad_s = omega_body(t);
    s.nacelle_yaw_rad = q(6, t);
    s.nacelle_yaw_rate_rad_s = qd(6, t);
    s.nacelle_yaw_acceleration_rad_s2 = qdd(6, t);
    s.rotor_azimuth_rad = q(7, t) + 1.3 * t;
    s.rotor_speed_rad_s = qd(7, t) + 1.3;
    s.generator_azimuth_rad = q(8, t) + 1.3 * t;
    s.generator_speed_rad_s = qd(8, t) + 1.3;
    for (int j = 0; j < kMaxTowerModes; ++j) {
      s.tower_deflection_m[j] = 0.1 * q(11 + j, t);
      s.tower_deflection_rate_m_s[j] = 0.1 * qd(11 + j, t);
    }
    for (int b = 0; b < kMaxBlades; ++b) {
      s.blade_pitch_rad[b] = 0.2 * b;
      for (int j = 0; j < kMaxBladeModes; ++j) {
        s.blade_deflection_m[b][j] = q(15 + 3 * b + j, t);
        s.blade_deflection_rate_m_s[b][j] = qd(15 + 3 * b + j, t);
      }
    }
    return s;
  }
  GeneralisedVector udot(double t) const {
    GeneralisedVector a = GeneralisedVector::Zero();
    a.segment<3>(0) = Vec3(qdd(0, t), qdd(1, t), qdd(2, t));
    // ω̇_b = E θ̈ + Ė θ̇; Ė by a central difference (h = 1e-6: error ~1e-12, far below the checks).
    const double h = 1e-6;
    const Mat3 e_dot = (euler123_rate_matrix(angles(t + h)) - euler123_rate_matrix(angles(t - h))) / (2 * h);
    a.segment<3>(3) = euler123_rate_matrix(angles(t)) * Vec3(qdd(3, t), qdd(4, t), qdd(5, t)) + e_dot * angle_rates(t);
    a[kRotor] = qdd(7, t);
    a[kGenerator] = qdd(8, t);
    for (int j = 0; j < kMaxTowerModes; ++j) a[kTower + j] = 0.1 * qdd(11 + j, t);
    for (int j = 0; j < kMaxBlades * kMaxBladeModes; ++j) a[kBlade + j] = qdd(15 + j, t);
    return a;
  }
};

ChainKinematics at(const Model& model, const Trajectory& tr, double t) {
  ChainKinematics k;
  chain_kinematics(model, tr.state(t), k);
  return k;
}

}  // namespace

TEST_CASE("chain velocities and accelerations equal finite differences of positions",
          "[verification][multibody][kinematics]") {
  Params p = oc3_hywind_params();
  p.nacelle.yaw_prescribed = true;
  const Model model = make_model(p);
  double worst_v = 0.0, worst_a = 0.0, worst_w = 0.0, worst_alpha = 0.0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const Trajectory tr(seed);
    const double t = 0.37 * seed;
    const ChainKinematics k = at(model, tr, t);
    const GeneralisedVector udot = tr.udot(t);
    const double hv = 1e-4, ha = 1e-3;  // central differences: truncation ~h², round-off ~1e-16 |p|/h^n
    const ChainKinematics kp = at(model, tr, t + hv), km = at(model, tr, t - hv);
    const ChainKinematics kpa = at(model, tr, t + ha), kma = at(model, tr, t - ha);
    auto check_point = [&](auto member) {
      const PointKinematics& p0 = k.*member;
      const Vec3 v_fd = ((kp.*member).position_m - (km.*member).position_m) / (2 * hv);
      const Vec3 a_fd = ((kpa.*member).position_m - 2 * p0.position_m + (kma.*member).position_m) / (ha * ha);
      worst_v = std::max(worst_v, (p0.velocity_m_s - v_fd).norm() / std::max(1.0, v_fd.norm()));
      worst_a = std::max(worst_a, (acceleration(p0, udot) - a_fd).norm() / std::max(1.0, a_fd.norm()));
    };
    check_point(&ChainKinematics::tower_top);
    check_point(&ChainKinematics::base_cm);
    check_point(&ChainKinematics::nacelle_cm);
    check_point(&ChainKinematics::imu);
    check_point(&ChainKinematics::apex);
    check_point(&ChainKinematics::rotor_cm);
    for (int i = 0; i < 3; ++i) {
      const Vec3 v_fd = (kp.blade_root[i].position_m - km.blade_root[i].position_m) / (2 * hv);
      const Vec3 a_fd = (kpa.blade_root[i].position_m - 2 * k.blade_root[i].position_m + kma.blade_root[i].position_m) / (ha * ha);
      worst_v = std::max(worst_v, (k.blade_root[i].velocity_m_s - v_fd).norm() / std::max(1.0, v_fd.norm()));
      worst_a = std::max(worst_a, (acceleration(k.blade_root[i], udot) - a_fd).norm() / std::max(1.0, a_fd.norm()));
      // Root frame: ω_f from Ṫ by differences (seed 000 eq. 2.2), vs frame_motion().
      const FrameMotion fm = frame_motion(k.blade_root[i], k.rotor, k.blade_root_orientation[i], udot);
      const Mat3 t_dot = (kp.blade_root_orientation[i] - km.blade_root_orientation[i]) / (2 * hv);
      const Vec3 w_fd = body_angular_velocity(k.blade_root_orientation[i], t_dot);
      worst_w = std::max(worst_w, (fm.angular_velocity_rad_s - w_fd).norm() / std::max(1.0, w_fd.norm()));
      const Mat3 t_ddot = (kpa.blade_root_orientation[i] - 2 * k.blade_root_orientation[i] + kma.blade_root_orientation[i]) / (ha * ha);
      const Vec3 alpha_fd = body_angular_acceleration(k.blade_root_orientation[i], t_dot, t_ddot);
      worst_alpha = std::max(worst_alpha, (fm.angular_acceleration_rad_s2 - alpha_fd).norm() / std::max(1.0, alpha_fd.norm()));
    }
    // Body angular velocities (g) against Ṫ Tᵀ by differences, angular accelerations against
    // differences of ω_g.
    auto check_rotation = [&](auto member) {
      const RotationKinematics& r0 = k.*member;
      const Mat3 t_dot = ((kp.*member).orientation - (km.*member).orientation) / (2 * hv);
      const Vec3 w_fd = spatial_angular_velocity(r0.orientation, t_dot);
      worst_w = std::max(worst_w, (r0.angular_velocity_rad_s - w_fd).norm() / std::max(1.0, w_fd.norm()));
      const Vec3 alpha_fd = ((kp.*member).angular_velocity_rad_s - (km.*member).angular_velocity_rad_s) / (2 * hv);
      worst_alpha = std::max(worst_alpha, (angular_acceleration(r0, udot) - alpha_fd).norm() / std::max(1.0, alpha_fd.norm()));
    };
    check_rotation(&ChainKinematics::base);
    check_rotation(&ChainKinematics::nacelle);
    check_rotation(&ChainKinematics::rotor);
  }
  INFO("worst relative errors: v " << worst_v << ", a " << worst_a << ", ω " << worst_w << ", α " << worst_alpha);
  // Tolerances: 10× the measured differences (truncation h²/6 |p'''|, h²/12 |p''''| of the central
  // differences with h = 1e-4 s and 1e-3 s, plus round-off), rounded up to one figure.
  CHECK(worst_v < 1e-7);
  CHECK(worst_a < 1e-5);
  CHECK(worst_w < 1e-7);
  CHECK(worst_alpha < 1e-5);
  WARN("kinematics FD: v " << worst_v << ", a " << worst_a << ", w " << worst_w << ", alpha " << worst_alpha);
}

TEST_CASE("generator angular velocity is N times the generator speed about the shaft axis",
          "[unit][multibody][kinematics]") {
  const Model model = make_model(oc3_hywind_params());
  State s = initial_state(model);
  s.rotor_speed_rad_s = 1.2;
  s.generator_speed_rad_s = 1.1;
  ChainKinematics k;
  chain_kinematics(model, s, k);
  const Vec3 e_s = k.shaft.orientation.col(0);
  // Exact identity (floating point): platform at rest, so ω_gen = N θ̇_g e_s.
  CHECK((k.generator.angular_velocity_rad_s - 97.0 * 1.1 * e_s).norm() < 1e-12);
  CHECK((k.rotor.angular_velocity_rad_s - 1.2 * e_s).norm() < 1e-14);
  // Hub height: 87.6 + Twr2Shft + |OverHang| sin 5° = 90.0 m (NREL/TP-500-38060 Table 1-1: hub height 90 m).
  CHECK(k.apex.position_m.z() == Approx(87.6 + 1.96256 + 5.0191 * std::sin(5.0 * M_PI / 180)).epsilon(1e-14));
  CHECK(k.apex.position_m.z() == Approx(90.0).margin(0.01));
  // The upwind end of the shaft is raised (ElastoDyn ShftTilt < 0): x_s points down-wind and down.
  CHECK(e_s.x() > 0.0);
  CHECK(e_s.z() < 0.0);
}

TEST_CASE("the tower axis crosses sea level where tower influence needs it, wherever the reference point is", "[unit][multibody]") {
  Params p = oc3_hywind_params();
  p.platform.reference_height_m = 10.0;  // reference point above SWL: not on the waterline
  p.initial_conditions.platform_angles_deg = Vec3(3.0, 8.0, 20.0);
  p.initial_conditions.platform_position_m = Vec3(5.0, -2.0, 1.0);
  const Model model = make_model(p);
  ChainKinematics chain;
  chain_kinematics(model, Multibody::make_state(model), chain);
  const Vec3 at_sea_level = tower_axis_at_sea_level(chain);
  CHECK(std::abs(at_sea_level.z()) < 1e-12);
  // On the axis through the tower base along z_b: the offset is parallel to the axis.
  const Vec3 offset = chain.tower_base.position_m - at_sea_level;
  CHECK(offset.cross(chain.base.orientation.col(2)).norm() < 1e-9 * offset.norm());
}

TEST_CASE("flexible tower and Rayleigh-Ritz blade points move as finite differences of their positions",
          "[verification][multibody][kinematics][rr_blades]") {
  // The deflected blade stations (blade_station_point) and tower points on a moving, bending tower
  // with bending, pitched blades: the velocities, Jacobians and bias accelerations that Kane's
  // equations take, against central differences along the same random trajectories (all 24
  // coordinates), as the chain's points above.
  Params p = oc3_hywind_params();
  p.nacelle.yaw_prescribed = true;
  set_oc3_flexible_tower(p);
  p.rotor.rayleigh_ritz_blade = flexbody::read_elastodyn_blade(FOWTSIM_SOURCE_DIR "/inputs/nrel5mw/blade_elastodyn.yaml");
  p.rotor.blade_station_spans_m = {10.0, 30.0, 50.0};
  const Model model = make_model(p);
  double worst_v = 0.0, worst_a = 0.0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const Trajectory tr(seed);
    const double t = 0.37 * seed;
    const double hv = 1e-4, ha = 1e-3;
    auto position = [&](double time, int b, int s) {
      ChainKinematics k;
      const State st = tr.state(time);
      chain_kinematics(model, st, k);
      return s < 0 ? tower_point(model, st, k, 50.0).position_m : blade_station_point(model, st, k, b, s).position_m;
    };
    const State st = tr.state(t);
    ChainKinematics k;
    chain_kinematics(model, st, k);
    const GeneralisedVector udot = tr.udot(t);
    for (int b = 0; b < 3; ++b)
      for (int s = -1; s < model.rr_blades.station_count; ++s) {
        const PointKinematics p0 = s < 0 ? tower_point(model, st, k, 50.0) : blade_station_point(model, st, k, b, s);
        const Vec3 v_fd = (position(t + hv, b, s) - position(t - hv, b, s)) / (2 * hv);
        const Vec3 a_fd = (position(t + ha, b, s) - 2 * p0.position_m + position(t - ha, b, s)) / (ha * ha);
        worst_v = std::max(worst_v, (p0.velocity_m_s - v_fd).norm() / std::max(1.0, v_fd.norm()));
        worst_a = std::max(worst_a, (acceleration(p0, udot) - a_fd).norm() / std::max(1.0, a_fd.norm()));
      }
  }
  WARN("flexible points FD: v " << worst_v << ", a " << worst_a);
  // As the chain's points above (same differences and steps).
  CHECK(worst_v < 1e-7);
  CHECK(worst_a < 1e-5);
}
