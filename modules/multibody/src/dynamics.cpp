#include "fowtsim/multibody/dynamics.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <type_traits>

#include <Eigen/Cholesky>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation.hpp"
#include "fowtsim/multibody/blade_body.hpp"
#include "fowtsim/multibody/tower_body.hpp"

namespace fowtsim::multibody {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// One rigid body as seen by the equations of motion: CM point, rotation, inertia in g.
struct BodyView {
  double mass;
  const PointKinematics* cm;
  const RotationKinematics* rotation;
  Mat3 inertia_g;
};

// The four bodies: base, nacelle, rotor and the (massless, axisymmetric) generator rotor.
int body_views(const Model& model, const ChainKinematics& k, BodyView (&views)[4]) {
  auto world = [](const Mat3& t, const Mat3& i) { return Mat3(t * i * t.transpose()); };
  views[0] = {model.base.mass_kg, &k.base_cm, &k.base, world(k.base.orientation, model.base.inertia_kg_m2)};
  views[1] = {model.nacelle.mass_kg, &k.nacelle_cm, &k.nacelle,
              world(k.nacelle.orientation, model.nacelle.inertia_kg_m2)};
  views[2] = {model.rotor.mass_kg, &k.rotor_cm, &k.rotor, world(k.rotor.orientation, model.rotor.inertia_kg_m2)};
  const Vec3 e_s = k.shaft.orientation.col(0);
  views[3] = {0.0, &k.apex, &k.generator, Mat3(model.generator_inertia_kg_m2 * e_s * e_s.transpose())};
  return 4;
}

// The chain's Jacobians touch only its first kBlade columns (kinematics.hpp): products over those.
constexpr int kChain = kBlade;

// Pᵀ A P with P = [J_v,ref; J_ω,base] (6 × kMaxDofs).
void add_added_mass(const ChainKinematics& k, const Mat6& added_mass, GeneralisedMatrix& m) {
  Eigen::Matrix<double, 6, kChain> p;
  p.topRows<3>() = k.reference.jacobian.leftCols<kChain>();
  p.bottomRows<3>() = k.base.jacobian.leftCols<kChain>();
  m.topLeftCorner<kChain, kChain>().noalias() += p.transpose().lazyProduct(added_mass * p);
}

// Qᵀ A Q with Q = [J_v,apex; J_ω,shaft] (6 × kMaxDofs): an apparent mass carried by the shaft.
void add_rotor_added_mass(const ChainKinematics& k, const Mat6& added_mass, GeneralisedMatrix& m) {
  Eigen::Matrix<double, 6, kChain> q;
  q.topRows<3>() = k.apex.jacobian.leftCols<kChain>();
  q.bottomRows<3>() = k.shaft.jacobian.leftCols<kChain>();
  m.topLeftCorner<kChain, kChain>().noalias() += q.transpose().lazyProduct(added_mass * q);
}

GeneralisedMatrix assemble_mass(const Model& model, const State& state, const ChainKinematics& k,
                                const Mat6& added_mass, const Mat6& rotor_added_mass = Mat6::Zero()) {
  BodyView views[4];
  const int n = body_views(model, k, views);
  GeneralisedMatrix m = GeneralisedMatrix::Zero();
  for (int i = 0; i < n; ++i) {
    const BodyView& b = views[i];
    const auto v = b.cm->jacobian.leftCols<kChain>();
    const auto w = b.rotation->jacobian.leftCols<kChain>();
    m.topLeftCorner<kChain, kChain>().noalias() += (b.mass * v).transpose().lazyProduct(v);
    m.topLeftCorner<kChain, kChain>().noalias() += w.transpose().lazyProduct(b.inertia_g * w);
  }
  // Flexible tower: its mass with the elastic Jacobian columns.
  if (model.flexible_tower.mode_count > 0) add_flexible_body_mass(model.flexible_tower.inertia, tower_motion(model, state, k), m);
  for (int b = 0; b < model.blade_count && model.rr_blades.mode_count > 0; ++b)
    add_flexible_body_mass(model.rr_blades.inertia, blade_motion(model, state, k, b), m);
  add_added_mass(k, added_mass, m);
  if (!rotor_added_mass.isZero(0.0)) add_rotor_added_mass(k, rotor_added_mass, m);
  return m;
}

}  // namespace

State initial_state(const Model& model) {
  const InitialConditions& ic = model.params.initial_conditions;
  State s;
  s.position_m = ic.platform_position_m;
  s.orientation = Eigen::Quaterniond(euler123_to_matrix(ic.platform_angles_deg * kDeg)).normalized();
  s.velocity_m_s = ic.platform_velocity_m_s;
  s.angular_velocity_rad_s = ic.platform_angular_velocity_deg_s * kDeg;
  s.rotor_azimuth_rad = ic.azimuth_deg * kDeg;
  s.rotor_speed_rad_s = ic.rotor_speed_rpm * std::numbers::pi / 30.0;
  s.generator_azimuth_rad = s.rotor_azimuth_rad;
  s.generator_speed_rad_s = s.rotor_speed_rad_s;
  s.nacelle_yaw_rad = ic.nacelle_yaw_deg * kDeg;
  // Tower-top deflections go to the first mode of each direction, as ElastoDyn does (q = TTDsp).
  const FlexibleTower& tower = model.flexible_tower;
  if (tower.fore_aft_count > 0) s.tower_deflection_m[0] = ic.tower_top_deflection_m[0];
  if (tower.mode_count > tower.fore_aft_count) s.tower_deflection_m[tower.fore_aft_count] = ic.tower_top_deflection_m[1];
  // A held platform DOF does not move (u = [v_ref in g; ω in b], DOFs 0…5 in that order).
  for (int i = 0; i < 3; ++i) {
    if (model.acceleration_given[kSurge + i]) s.velocity_m_s[i] = 0.0;
    if (model.acceleration_given[kRoll + i]) s.angular_velocity_rad_s[i] = 0.0;
  }
  return s;
}

GeneralisedMatrix generalised_mass(const Model& model, const State& state, const Mat6& added_mass) {
  ChainKinematics k;
  chain_kinematics(model, state, k);
  return assemble_mass(model, state, k, added_mass);
}

void evaluate(const Model& model, const State& state, const AppliedLoads& loads, double t,
              Evaluation& out) {
  ChainKinematics& k = out.kinematics;
  chain_kinematics(model, state, k);
  out.mass = assemble_mass(model, state, k, loads.platform_added_mass, loads.rotor_added_mass);

  GeneralisedVector& f = out.force;
  f.setZero();
  const Vec3 gravity(0.0, 0.0, loads.gravity ? -model.params.gravity_m_s2 : 0.0);
  BodyView views[4];
  const int n = body_views(model, k, views);
  for (int i = 0; i < n; ++i) {
    const BodyView& b = views[i];
    const Vec3& w = b.rotation->angular_velocity_rad_s;
    // Weight minus the velocity-product part of the inertia force and moment (Kane's F*).
    f.noalias() += b.cm->jacobian.transpose() * (b.mass * (gravity - b.cm->bias_acceleration_m_s2));
    f.noalias() -= b.rotation->jacobian.transpose() *
                   (b.inertia_g * b.rotation->bias_angular_acceleration_rad_s2 + w.cross(b.inertia_g * w));
  }
  // Flexible tower: weight and velocity-product inertia of its mass; elastic (K_q), geometric (K^T from
  // the weight above, with gravity) and structural damping forces on the modal coordinates.
  const FlexibleTower& tower = model.flexible_tower;
  if (tower.mode_count > 0) {
    const FlexibleBodyDAlembert bias =
        flexible_body_dalembert(tower.inertia, tower_motion(model, state, k), GeneralisedVector::Zero(), gravity);
    f.noalias() += k.reference.jacobian.transpose() * bias.force_N + k.base.jacobian.transpose() * bias.moment_N_m;
    for (int i = 0; i < tower.mode_count; ++i) f[kTower + i] += bias.modal_N[i];
  }
  for (int i = 0; i < tower.mode_count; ++i) {
    double elastic = 0.0;
    for (int j = 0; j < tower.mode_count; ++j) {
      const double stiffness = tower.stiffness(i, j) +
                               (loads.gravity ? model.params.gravity_m_s2 * tower.geometric_stiffness_per_g(i, j) : 0.0);
      elastic += stiffness * state.tower_deflection_m[j] + tower.damping(i, j) * state.tower_deflection_rate_m_s[j];
    }
    f[kTower + i] -= elastic;
  }

  // Rayleigh–Ritz blades: weight and velocity-product inertia (the spin's in-plane softening
  // included, through ω × (ω × ρ)); elastic K, centrifugal stiffening Ω² G (seed 002 eq. 26: linear
  // shapes carry no radial shortening, so the axial load's work must be added) and damping; the
  // station loads through the deflected stations.
  const RayleighRitzBlades& rr = model.rr_blades;
  for (int b = 0; b < model.blade_count && rr.mode_count > 0; ++b) {
    const FlexibleBodyMotion body = blade_motion(model, state, k, b);
    const FlexibleBodyDAlembert bias = flexible_body_dalembert(rr.inertia, body, GeneralisedVector::Zero(), gravity);
    f.noalias() += body.origin->jacobian.transpose() * bias.force_N + k.rotor.jacobian.transpose() * bias.moment_N_m;
    const double spin2 = state.rotor_speed_rad_s * state.rotor_speed_rad_s;
    const Eigen::Map<const Vec3> q(state.blade_deflection_m[b].data()), qd(state.blade_deflection_rate_m_s[b].data());
    const Vec3 elastic = (rr.stiffness + spin2 * rr.centrifugal_stiffness) * q + rr.damping * qd;
    for (int j = 0; j < rr.mode_count; ++j) f[body.first_dof + j] += bias.modal_N[j] - elastic[j];
    // The station loads through the stations' Jacobians, Σ J_sᵀ F_s + J_θ,sᵀ M_s, summed per part:
    // their resultant at the root through the root's and the hub's Jacobians, and each mode's share
    // F_s · T φ_j(s) + M_s · T θ_j(s) (blade_rotation_shape).
    Vec3 force = Vec3::Zero(), moment = Vec3::Zero();  // about the root
    Vec3 modal_force = Vec3::Zero();
    const Mat3& t_gf = body.orientation;
    for (int s = 0; s < loads.blade_station_load_count; ++s) {
      const BladeStationLoad& load = loads.blade_station_loads[b][s];
      const BladeStation& station = rr.stations[s];
      Vec3 rho(0.0, 0.0, station.span_m);
      for (int j = 0; j < rr.mode_count; ++j) rho += q[j] * station.shape[j];
      const Vec3 f_local = t_gf.transpose() * load.force_N, m_local = t_gf.transpose() * load.moment_N_m;
      force += load.force_N;
      moment += t_gf * rho.cross(f_local) + load.moment_N_m;
      for (int j = 0; j < rr.mode_count; ++j)
        modal_force[j] += station.shape[j].dot(f_local) + blade_rotation_shape(station, j).dot(m_local);
    }
    f.noalias() += body.origin->jacobian.transpose() * force + k.rotor.jacobian.transpose() * moment;
    f.segment<kMaxBladeModes>(body.first_dof) += modal_force;
  }

  // Added mass: its bias part −Pᵀ A [a_r,bias; α_bias] vanishes because a_r = v̇ and α = T_gb ω̇_b
  // have no velocity-product terms in these generalised speeds.

  // Platform loads at r.
  f.noalias() += k.reference.jacobian.transpose() * loads.platform_force_N;
  f.noalias() += k.base.jacobian.transpose() * loads.platform_moment_N_m;
  // Tower point loads where they act: through the deflected point's Jacobian they reach the base
  // body and, on a flexible tower, the modes (Q_j = F · φ_j(h) T_gb d_j).
  for (int i = 0; i < loads.tower_load_count; ++i) {
    const TowerPointLoad& load = loads.tower_loads[i];
    f.noalias() += tower_point(model, state, k, load.height_m).jacobian.transpose() * load.force_N;
  }

  // Rotor loads: everything reduced to a force at the apex and a moment about it.
  Vec3 rotor_force = loads.rotor_force_N;
  Vec3 rotor_moment = loads.rotor_moment_N_m;
  for (int i = 0; i < kMaxBlades; ++i) {
    const RootLoads& root = loads.blade_root[i];
    rotor_force += root.force_N;
    rotor_moment += root.moment_N_m + (root.point_m - k.apex.position_m).cross(root.force_N);
  }
  f.noalias() += k.apex.jacobian.transpose() * rotor_force;
  f.noalias() += k.rotor.jacobian.transpose() * rotor_moment;
  // The shaft's apparent mass: Qᵀ A Q u̇ is on the left; its bias part −A [a_bias,apex; α_bias,shaft]
  // (the velocity products) is a load.
  if (!loads.rotor_added_mass.isZero(0.0)) {
    Vec6 bias;
    bias << k.apex.bias_acceleration_m_s2, k.shaft.bias_angular_acceleration_rad_s2;
    const Vec6 load = -(loads.rotor_added_mass * bias);
    f.noalias() += k.apex.jacobian.transpose() * load.head<3>();
    f.noalias() += k.shaft.jacobian.transpose() * load.tail<3>();
  }

  // Drivetrain: generator torque on the HSS (LSS-equivalent N T), shaft spring and damper.
  f[model.generator_dof] -= model.gearbox_ratio * loads.generator_torque_N_m;
  if (model.generator_dof == kGenerator) {
    const DrivetrainParams& d = model.params.drivetrain;
    const double torque = d.torsional_stiffness_N_m_rad * (state.rotor_azimuth_rad - state.generator_azimuth_rad) +
                          d.torsional_damping_N_m_s_rad * (state.rotor_speed_rad_s - state.generator_speed_rad_s);
    f[kRotor] -= torque;
    f[kGenerator] += torque;
  }

  // Solve; unused rows (the generator with a rigid shaft, tower rows beyond the model's modes)
  // are made the identity so one fixed-size Cholesky serves every case.
  GeneralisedMatrix m = out.mass;
  for (int i = kGenerator; i < kMaxDofs; ++i) {
    if (dof_active(model, i)) continue;
    m(i, i) = 1.0;
    f[i] = 0.0;
  }
  // Given accelerations (held DOFs, prescribed spin, a drivetrain the brake holds): move their
  // columns to the right-hand side and replace their rows by u̇_i = given.
  const int gen = model.generator_dof;
  const bool locked = loads.drivetrain_locked && !model.acceleration_given[gen];
  const double f_gen = f[gen];  // before the substitution, for the lock's reaction
  for (int i = 0; i < model.dof_count; ++i) {
    if (!model.acceleration_given[i] && !(locked && i == gen)) continue;
    const bool prescribed = model.params.dofs.rotor == RotorSpin::prescribed && model.acceleration_given[i];
    const double a = !prescribed || i < kRotor || i >= kTower ? 0.0
                     : i == kRotor             ? state.rotor_acceleration_rad_s2
                                               : state.generator_acceleration_rad_s2;
    f.noalias() -= m.col(i) * a;
    m.row(i).setZero();
    m.col(i).setZero();
    m(i, i) = 1.0;
    f[i] = a;
  }
  // The rigid-tower model solves its 8 × 8 block with the same fixed-size Cholesky as before the
  // tower DOFs existed (bit-identical results); a flexible tower or blades the whole matrix.
  auto solve = [&](const auto& block, const auto& rhs) {
    const Eigen::LLT<std::remove_cvref_t<decltype(block)>> llt(block);
    if (llt.info() != Eigen::Success) {
      throw NumericalError({"multibody", t, "mass matrix M(q)",
                            "check the added mass handed in (it must be symmetric positive semi-definite)"},
                           "the generalised mass matrix is not positive definite");
    }
    return llt.solve(rhs).eval();
  };
  if (model.flexible_tower.mode_count == 0 && rr.mode_count == 0) {
    const Eigen::Matrix<double, kTower, kTower> rigid = m.topLeftCorner<kTower, kTower>();
    const Eigen::Matrix<double, kTower, 1> rigid_f = f.head<kTower>();
    out.acceleration.setZero();
    out.acceleration.head<kTower>() = solve(rigid, rigid_f);
  } else {
    out.acceleration = solve(m, f);
  }
  out.drivetrain_lock_torque_N_m = locked ? out.mass.row(gen).dot(out.acceleration) - f_gen : 0.0;
  for (int i = 0; i < kMaxDofs; ++i) {
    if (!std::isfinite(out.acceleration[i])) {
      throw NumericalError({"multibody", t, "generalised acceleration u̇[" + std::to_string(i) + "]",
                            "check the applied loads for NaN/Inf or reduce the time step"},
                           "non-finite acceleration");
    }
  }
}

Invariants invariants(const Model& model, const State& state, bool gravity) {
  ChainKinematics k;
  chain_kinematics(model, state, k);
  BodyView views[4];
  const int n = body_views(model, k, views);
  Invariants inv;
  for (int i = 0; i < n; ++i) {
    const BodyView& b = views[i];
    const Vec3& v = b.cm->velocity_m_s;
    const Vec3& w = b.rotation->angular_velocity_rad_s;
    inv.kinetic_energy_J += 0.5 * b.mass * v.squaredNorm() + 0.5 * w.dot(b.inertia_g * w);
    inv.linear_momentum_N_s += b.mass * v;
    inv.angular_momentum_N_m_s += b.cm->position_m.cross(b.mass * v) + b.inertia_g * w;
    if (gravity) inv.potential_energy_J += b.mass * model.params.gravity_m_s2 * b.cm->position_m.z();
  }
  // Flexible bodies: kinetic energy ½ uᵀ M_body u, momenta, weight.
  const GeneralisedVector u = generalised_velocities(model, state);
  auto add_flexible = [&](const ShapeIntegrals& in, const FlexibleBodyMotion& body) {
    GeneralisedMatrix mass = GeneralisedMatrix::Zero();
    add_flexible_body_mass(in, body, mass);
    inv.kinetic_energy_J += 0.5 * u.dot(mass * u);
    const FlexibleBodyMomentum momentum = flexible_body_momentum(in, body);
    inv.linear_momentum_N_s += momentum.linear_N_s;
    inv.angular_momentum_N_m_s += momentum.angular_N_m_s;
    const Vec3 cm_moment = body.orientation * flexible_body_mass_properties(in, body).first_moment_kg_m;
    if (gravity) inv.potential_energy_J += model.params.gravity_m_s2 * (in.mass_kg * body.origin->position_m.z() + cm_moment.z());
  };
  const FlexibleTower& tower = model.flexible_tower;
  if (tower.mode_count > 0) add_flexible(tower.inertia, tower_motion(model, state, k));
  const RayleighRitzBlades& rr = model.rr_blades;
  for (int b = 0; b < model.blade_count && rr.mode_count > 0; ++b) {
    add_flexible(rr.inertia, blade_motion(model, state, k, b));
    // Strain energy of K only: Ω² G depends on the speed and has no potential.
    const Eigen::Map<const Vec3> q(state.blade_deflection_m[b].data());
    inv.potential_energy_J += 0.5 * q.dot(rr.stiffness * q);
  }
  for (int i = 0; i < tower.mode_count; ++i)
    for (int j = 0; j < tower.mode_count; ++j)
      inv.potential_energy_J += 0.5 * state.tower_deflection_m[i] * state.tower_deflection_m[j] *
                                (tower.stiffness(i, j) + (gravity ? model.params.gravity_m_s2 *
                                                                        tower.geometric_stiffness_per_g(i, j) : 0.0));
  if (model.generator_dof == kGenerator) {
    const double twist = state.rotor_azimuth_rad - state.generator_azimuth_rad;
    inv.potential_energy_J += 0.5 * model.params.drivetrain.torsional_stiffness_N_m_rad * twist * twist;
  }
  return inv;
}

}  // namespace fowtsim::multibody
