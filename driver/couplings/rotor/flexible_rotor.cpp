#include "rotor/flexible_rotor.hpp"

#include <cmath>

#include <Eigen/LU>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation_vector.hpp"
#include "rotor/blade_aero_map.hpp"
#include "rotor/rotor_aero.hpp"

namespace fowtsim::driver {
namespace {

// Spin and pitch of the rotor at one instant: everything besides the shaft motion that the
// blade frames depend on.
struct SpinPose {
  double azimuth = 0.0, speed = 0.0, acceleration = 0.0;
  std::array<double, kBlades> pitch{}, pitch_rate{}, pitch_acceleration{};
};

// Hub and pitched root frame i (flexible_rotor.hpp) by the rigid-body rules:
//   ω_h = ω_s + ψ̇ e,  α_h = α_s + ψ̈ e + ψ̇ ω_s × e,
//   ω_f = ω_h − β̇ z,  α_f = α_h − β̈ z − β̇ ω_h × z   (pitch −β about the pitch axis z = z_r),
//   a_root = a_apex + α_h × ρ + ω_h × (ω_h × ρ).
BladeFrame blade_frame(const FlexibleRotorParams& p, const ShaftMotion& s, const SpinPose& spin, int i) {
  const Vec3 e = s.orientation.col(0);
  const Mat3 t_gh = s.orientation * rotation_matrix(Vec3(spin.azimuth, 0.0, 0.0));
  const Mat3 t_gr = t_gh * p.root_orientation_h[i];
  BladeFrame f;
  f.orientation = t_gr * rotation_matrix(Vec3(0.0, 0.0, -spin.pitch[i]));
  f.arm_m = t_gh * p.root_h[i];
  f.root_m = s.apex_position_m + f.arm_m;
  const Vec3 w_h = s.angular_velocity_rad_s + spin.speed * e;
  const Vec3 a_h = s.angular_acceleration_rad_s2 + spin.acceleration * e + spin.speed * s.angular_velocity_rad_s.cross(e);
  const Vec3 z = t_gr.col(2);
  f.root_velocity_m_s = s.apex_velocity_m_s + w_h.cross(f.arm_m);
  f.root_acceleration_m_s2 = s.apex_acceleration_m_s2 + a_h.cross(f.arm_m) + w_h.cross(w_h.cross(f.arm_m));
  f.angular_velocity_rad_s = w_h - spin.pitch_rate[i] * z;
  f.angular_acceleration_rad_s2 = a_h - spin.pitch_acceleration[i] * z - spin.pitch_rate[i] * w_h.cross(z);
  return f;
}

beam::FrameKinematics in_f(const BladeFrame& f, double gravity) {
  const Mat3 t_fg = f.orientation.transpose();
  beam::FrameKinematics k;
  k.acceleration_m_s2 = t_fg * f.root_acceleration_m_s2;
  k.angular_velocity_rad_s = t_fg * f.angular_velocity_rad_s;
  k.angular_acceleration_rad_s2 = t_fg * f.angular_acceleration_rad_s2;
  k.gravity_m_s2 = t_fg * Vec3(0.0, 0.0, -gravity);
  return k;
}

// A root load in f → force in g and moment about the apex in g.
void about_apex(const BladeFrame& f, const Vec6& root_f, Vec3& force, Vec3& moment) {
  force = f.orientation * root_f.head<3>();
  moment = f.orientation * root_f.tail<3>() + f.arm_m.cross(force);
}

}  // namespace

ShaftMotion shaft_motion(const multibody::ChainKinematics& chain, const multibody::GeneralisedVector& udot) {
  ShaftMotion s;
  s.apex_position_m = chain.apex.position_m;
  s.apex_velocity_m_s = chain.apex.velocity_m_s;
  s.apex_acceleration_m_s2 = multibody::acceleration(chain.apex, udot);
  s.orientation = chain.shaft.orientation;
  s.angular_velocity_rad_s = chain.shaft.angular_velocity_rad_s;
  s.angular_acceleration_rad_s2 = multibody::angular_acceleration(chain.shaft, udot);
  s.tower_base_m = multibody::tower_axis_at_sea_level(chain);
  s.tower_axis = chain.base.orientation.col(2);
  return s;
}

ShaftMotion interpolate(const ShaftMotion& a, const ShaftMotion& b, double x) {
  ShaftMotion m;
  m.apex_position_m = a.apex_position_m + x * (b.apex_position_m - a.apex_position_m);
  m.apex_velocity_m_s = a.apex_velocity_m_s + x * (b.apex_velocity_m_s - a.apex_velocity_m_s);
  m.apex_acceleration_m_s2 = a.apex_acceleration_m_s2 + x * (b.apex_acceleration_m_s2 - a.apex_acceleration_m_s2);
  m.orientation = a.orientation * rotation_matrix(x * rotation_vector(a.orientation.transpose() * b.orientation));
  m.angular_velocity_rad_s = a.angular_velocity_rad_s + x * (b.angular_velocity_rad_s - a.angular_velocity_rad_s);
  m.angular_acceleration_rad_s2 =
      a.angular_acceleration_rad_s2 + x * (b.angular_acceleration_rad_s2 - a.angular_acceleration_rad_s2);
  m.tower_base_m = a.tower_base_m + x * (b.tower_base_m - a.tower_base_m);
  m.tower_axis = (a.tower_axis + x * (b.tower_axis - a.tower_axis)).normalized();
  return m;
}

FlexibleRotor::FlexibleRotor(FlexibleRotorParams params, const RotorAero* aero, const BladeAeroMap* map)
    : params_(std::move(params)), aero_(aero), map_(map) {
  if (params_.dynamics.integrator != beam::Integrator::generalized_alpha)
    throw InputError({"blades", std::nullopt, "integrator", "generalized_alpha"},
                     "flexible blades on the turbine need the generalized_alpha integrator (the rotor spin is solved "
                     "together with its step)");
  for (int b = 0; b < kBlades; ++b) {
    steppers_[b] = std::make_unique<beam::DynamicStepper>(params_.blade, params_.dynamics);
    aero_loads_[b].assign(static_cast<std::size_t>(params_.blade.node_count()), Vec6::Zero());
    inputs_[b].node_loads.assign(static_cast<std::size_t>(params_.blade.node_count()), Vec6::Zero());
  }
  response_ = std::make_unique<beam::RootResponse>(params_.blade, params_.dynamics.spectral_radius);
}

double FlexibleRotor::apparent_mass_step(double dt_large, int n) const {
  const double rho = params_.dynamics.spectral_radius;
  const double am = (2.0 * rho - 1.0) / (rho + 1.0), af = rho / (rho + 1.0);
  const double beta = 0.25 * (1.0 - am + af) * (1.0 - am + af);
  const double w_m = 1.0 - am, w_k = (1.0 - af) * beta;  // w_k per h²
  return dt_large * std::sqrt((1.0 / 3.0 + 1.0 / (6.0 * n * n)) * w_m / (2.0 * w_k));
}

Mat6 FlexibleRotor::blade_apparent_mass_h(const ShaftMotion& shaft, const FlexibleRotorState& state, double h, int blade,
                                          bool gravity) {
  const Mat3 t_gh = shaft.orientation * rotation_matrix(Vec3(state.spin.rotor_azimuth_rad, 0.0, 0.0));
  const BladeFrame f = frame(shaft, blade, state);
  response_input_.frame = in_f(f, gravity ? params_.gravity_m_s2 : 0.0);
  const Mat6 per_unit = response_->compute(response_input_, h, state.blades[blade]);
  const Mat3 t_fh = f.orientation.transpose() * t_gh;
  const Vec3 arm_h = t_gh.transpose() * f.arm_m;
  Mat3 cross;
  cross << 0.0, -arm_h.z(), arm_h.y(), arm_h.z(), 0.0, -arm_h.x(), -arm_h.y(), arm_h.x(), 0.0;
  Mat6 x = Mat6::Zero();
  x.topLeftCorner<3, 3>() = t_fh;
  x.topRightCorner<3, 3>() = -t_fh * cross;
  x.bottomRightCorner<3, 3>() = t_fh;
  return -(x.transpose() * per_unit * x);
}

Mat6 FlexibleRotor::apparent_mass_h(const ShaftMotion& shaft, const FlexibleRotorState& state, double h,
                                    const RotorDemands& demands) {
  Mat6 blades = Mat6::Zero();
  for (int b = 0; b < kBlades; ++b) blades += blade_apparent_mass_h(shaft, state, h, b, demands.gravity);
  return with_spin_condensed(blades, h, demands);
}

Mat6 FlexibleRotor::with_spin_condensed(const Mat6& blades, double h, const RotorDemands& demands) const {
  Mat6 mass = blades;
  // The spin condensed out (header): e is x_h, index 3 of [a; α]; M = M_b − Bᵀ K⁻¹ B.
  if (params_.spin == SpinMode::free) {
    const double rho = params_.dynamics.spectral_radius;
    const double am = (2.0 * rho - 1.0) / (rho + 1.0), af = rho / (rho + 1.0);
    const double gamma = 0.5 - am + af, beta = 0.25 * (1.0 - am + af) * (1.0 - am + af);
    const double n = params_.gearbox_ratio, j_h = params_.hub_inertia_kg_m2, j_gen = params_.generator_inertia_kg_m2;
    Vec6 b_rotor = mass.col(3), b_generator = Vec6::Zero();
    b_rotor[3] += j_h;
    b_generator[3] = n * j_gen;
    const double j_rotor = j_h + mass(3, 3), j_generator = n * n * j_gen;
    if (!params_.torsional_flexibility) {  // ψ̈ = θ̈: one row, the sum; a brake holds both
      if (!demands.drivetrain_locked) {
        const Vec6 w = b_rotor + b_generator;
        mass -= w * w.transpose() / (j_rotor + j_generator);
      }
    } else {
      const double kappa = (1.0 - af) *
                           (params_.torsional_stiffness_N_m_rad * beta * h * h + params_.torsional_damping_N_m_s_rad * gamma * h) /
                           (1.0 - am);
      if (demands.drivetrain_locked) {  // θ̈ = 0: the rotor's row alone
        mass -= b_rotor * b_rotor.transpose() / (j_rotor + kappa);
      } else {
        Eigen::Matrix2d k;
        k << j_rotor + kappa, -kappa, -kappa, j_generator + kappa;
        Eigen::Matrix<double, 2, 6> b;
        b << b_rotor.transpose(), b_generator.transpose();
        mass -= b.transpose() * k.inverse() * b;
      }
    }
  }
  return 0.5 * (mass + mass.transpose());
}

FlexibleRotor::Data FlexibleRotor::make_data() const {
  Data d;
  for (beam::BeamState& s : d.state.blades) s = beam::make_state(params_.blade);
  return d;
}

BladeFrame FlexibleRotor::frame(const ShaftMotion& shaft, int blade, const FlexibleRotorState& state) const {
  SpinPose pose;
  pose.azimuth = state.spin.rotor_azimuth_rad;
  pose.speed = state.spin.rotor_speed_rad_s;
  pose.acceleration = state.spin.rotor_mean_acceleration_rad_s2;
  pose.pitch = state.pitch_rad;
  pose.pitch_rate = state.pitch_rate_rad_s;
  pose.pitch_acceleration = state.pitch_acceleration_rad_s2;
  return blade_frame(params_, shaft, pose, blade);
}

// Aerodynamic loads on the blades as they are now (explicit over the small step: the aero
// loads depend on the deflection and its rate, not on the acceleration, so lagging them one
// small step is not an added-mass exchange).
void FlexibleRotor::evaluate_aero(double t, const ShaftMotion& shaft, bool solve_induction, Data& d, RotorAero::Data* aero) {
  if (!aero_) return;
  std::array<BladeFrame, kBlades> frames;
  for (int b = 0; b < kBlades; ++b) {
    frames[b] = frame(shaft, b, d.state);
    map_->place(b, frames[b], d.state.blades[b], aero->input);
  }
  // The unsteady airfoil model's ω leaves out the spin's steady component along a coned or bent
  // blade's axis (as the rigid rotor does, RotorAero::evaluate): the static polars stand for it.
  aero::Aero::Input& placed = aero->input;
  const Vec3 spin = d.state.spin.rotor_speed_rad_s * shaft.orientation.col(0);
  for (Eigen::Index c = 0; c < placed.node_pitch_rate_rad_s.size(); ++c)
    placed.node_pitch_rate_rad_s(c) -= spin.dot(placed.node_orientation[static_cast<std::size_t>(c)].col(2));
  const Mat3 t_gh = shaft.orientation * rotation_matrix(Vec3(d.state.spin.rotor_azimuth_rad, 0.0, 0.0));
  aero_->evaluate_placed(t, shaft.apex_position_m, t_gh, d.state.spin.rotor_speed_rad_s, d.state.pitch_rad,
                         shaft.tower_base_m, shaft.tower_axis,
                         solve_induction ? aero::Induction::solve : aero::Induction::held, *aero);
  aero_->advance_states_placed(t, *aero);  // unsteady airfoil / dynamic inflow states to t (if on)
  for (int b = 0; b < kBlades; ++b) map_->distribute(b, frames[b], d.state.blades[b], aero->output, aero_loads_[b]);
}

void FlexibleRotor::start(const ShaftMotion& shaft, double azimuth_rad, double rotor_speed_rad_s, double pitch_rad,
                          const RotorDemands& demands, Start how, Data& d, RotorAero::Data* aero) {
  d.shaft = shaft;
  d.state.spin = SpinState{};
  d.state.spin.rotor_azimuth_rad = d.state.spin.generator_azimuth_rad = azimuth_rad;
  d.state.spin.rotor_speed_rad_s = d.state.spin.generator_speed_rad_s = rotor_speed_rad_s;
  d.state.pitch_rad.fill(pitch_rad);
  d.state.pitch_rate_rad_s.fill(0.0);
  d.state.pitch_acceleration_rad_s2.fill(0.0);
  for (int b = 0; b < kBlades; ++b) d.state.blades[b] = beam::make_state(params_.blade);
  const bool loads = how == Start::static_loads;
  const double gravity = demands.gravity && loads ? params_.gravity_m_s2 : 0.0;
  if (how != Start::undeformed) {
    // Static equilibrium under the steady frame motion (centrifugal), and with static_loads
    // gravity and the aero loads of the deflected blades: three passes of aero ↔ structure.
    for (int pass = 0; pass < (aero_ && loads ? 3 : 1); ++pass) {
      if (loads) evaluate_aero(0.0, shaft, true, d, aero);
      for (int b = 0; b < kBlades; ++b) {
        beam::BeamInput in;
        in.frame = in_f(frame(shaft, b, d.state), gravity);
        if (loads) in.node_loads = aero_loads_[b];
        beam::StaticOptions options;
        options.load_steps = pass == 0 ? 5 : 1;
        beam::solve_static(params_.blade, in, d.state.blades[b], options);
      }
    }
  }
  // The blades start moving rigidly with their root frames: relative velocities zero; the first
  // dynamic step solves for the consistent acceleration.
  for (beam::BeamState& s : d.state.blades) {
    for (Vec6& v : s.velocity) v.setZero();
    s.acceleration_valid = false;
    s.time_s = 0.0;
  }
  d.state.time_s = 0.0;
  evaluate_aero(0.0, shaft, true, d, aero);
  d.last = root_loads(shaft, d.state);
}

// Trapezoidal rule on the linear actuator (A-stable, second order).
void FlexibleRotor::advance_pitch(double dt, const std::array<double, 3>& command, FlexibleRotorState& state) const {
  const double w = params_.pitch_natural_frequency_rad_s, z = params_.pitch_damping_ratio;
  Eigen::Matrix2d a;
  a << 0.0, 1.0, -w * w, -2.0 * z * w;
  const Eigen::Matrix2d lhs_inverse = (Eigen::Matrix2d::Identity() - 0.5 * dt * a).inverse();
  for (int b = 0; b < kBlades; ++b) {
    const Eigen::Vector2d forcing(0.0, w * w * command[static_cast<std::size_t>(b)]);
    const Eigen::Vector2d x0(state.pitch_rad[b], state.pitch_rate_rad_s[b]);
    const Eigen::Vector2d x1 = lhs_inverse * (x0 + 0.5 * dt * (a * x0) + dt * forcing);
    state.pitch_acceleration_rad_s2[b] = (x1[1] - x0[1]) / dt;
    state.pitch_rad[b] = x1[0];
    state.pitch_rate_rad_s[b] = x1[1];
  }
}

FlexibleRotor::HubLoad FlexibleRotor::root_loads(const ShaftMotion& shaft, const FlexibleRotorState& state) const {
  const Mat3 t_gh = shaft.orientation * rotation_matrix(Vec3(state.spin.rotor_azimuth_rad, 0.0, 0.0));
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
  for (int b = 0; b < kBlades; ++b) {
    Vec3 f, m;
    about_apex(frame(shaft, b, state), beam::root_reaction(params_.blade, state.blades[b]), f, m);
    force += f;
    moment += m;
  }
  return {t_gh.transpose() * force, t_gh.transpose() * moment};
}

// One small step: blades and spin together (header). With generalized-α the balance is at
// t + (1 − αf)Δt, the spin's "mass" term takes ψ̈* = (1 − αm) a1 + αm a0 as the beam's does, and
// the blades' frame angular acceleration carries the same ψ̈*, so blades and hub are one
// generalized-α system in the spin. With s = a1 − a0 (per spin DOF), every blade's root torque
// about the shaft is τ_b0 + s τ_b1 (DynamicStepper::prepare), and the balances
//   rigid shaft:   (J_h + N²J_g) ψ̈* + (J_h + N J_g) e·α_s = Σ τ_b − N T_gen
//   flexible:      J_h ψ̈* + J_h e·α_s = Σ τ_b − T_shaft,
//                  N²J_g θ̈* + N J_g e·α_s = T_shaft − N T_gen,
//                  T_shaft = k (ψ − θ)_{1−αf} + c (ψ̇ − θ̇)_{1−αf}
// are linear in s: one or two scalar unknowns.
void FlexibleRotor::step(double t, double dt, const ShaftMotion& shaft, const RotorDemands& demands, bool solve_induction, Data& d,
                         RotorAero::Data* aero) {
  const double rho = params_.dynamics.spectral_radius;
  const double am = (2.0 * rho - 1.0) / (rho + 1.0), af = rho / (rho + 1.0);
  const double gamma = 0.5 - am + af, beta = 0.25 * (1.0 - am + af) * (1.0 - am + af);
  const double gravity = demands.gravity ? params_.gravity_m_s2 : 0.0;
  const bool held = params_.spin == SpinMode::held;
  const bool flexible = params_.torsional_flexibility && !held;
  const bool locked = demands.drivetrain_locked && !held;  // the brake holds the generator: its s keeps θ̈ = 0

  evaluate_aero(t, d.shaft, solve_induction, d, aero);  // on the blades at the start of the step
  advance_pitch(dt, demands.pitch_command_rad, d.state);

  // The spin predicted at the balance time with s = 0.
  SpinState& sp = d.state.spin;
  auto predict = [&](double x0, double v0, double a0, double& x1, double& v1) {
    v1 = v0 + dt * a0;
    x1 = x0 + dt * v0 + 0.5 * dt * dt * a0;
  };
  double psi1, psi_dot1, th1, th_dot1;
  predict(sp.rotor_azimuth_rad, sp.rotor_speed_rad_s, sp.rotor_acceleration_rad_s2, psi1, psi_dot1);
  predict(sp.generator_azimuth_rad, sp.generator_speed_rad_s, sp.generator_acceleration_rad_s2, th1, th_dot1);
  SpinPose pose;
  pose.azimuth = (1.0 - af) * psi1 + af * sp.rotor_azimuth_rad;
  pose.speed = (1.0 - af) * psi_dot1 + af * sp.rotor_speed_rad_s;
  pose.acceleration = sp.rotor_acceleration_rad_s2;  // ψ̈* at s = 0
  pose.pitch = d.state.pitch_rad;
  pose.pitch_rate = d.state.pitch_rate_rad_s;
  pose.pitch_acceleration = d.state.pitch_acceleration_rad_s2;

  const Vec3 e = shaft.orientation.col(0);
  const double e_alpha = e.dot(shaft.angular_acceleration_rad_s2);
  double tau0 = 0.0, tau1 = 0.0;
  for (int b = 0; b < kBlades; ++b) {
    const BladeFrame f = blade_frame(params_, shaft, pose, b);
    beam::BeamInput& in = inputs_[b];
    in.frame = in_f(f, gravity);
    in.node_loads = aero_loads_[b];
    beam::FrameAccelerationDirection dir;
    if (!held) {  // ψ̈* grows by (1 − αm) per unit s: the root frame turns faster about e
      dir.angular_acceleration_rad_s2 = (1.0 - am) * (f.orientation.transpose() * e);
      dir.acceleration_m_s2 = (1.0 - am) * (f.orientation.transpose() * e.cross(f.arm_m));
    }
    const beam::AffineRootLoad root = steppers_[b]->prepare(in, dir, dt, d.state.blades[b]);
    Vec3 force, moment;
    about_apex(f, root.at_zero, force, moment);
    tau0 += e.dot(moment);
    about_apex(f, root.per_unit, force, moment);
    tau1 += e.dot(moment);
  }

  const double n = params_.gearbox_ratio;
  const double j_h = params_.hub_inertia_kg_m2, j_gen = params_.generator_inertia_kg_m2;
  const double j_g = n * n * j_gen;  // generator inertia on the LSS
  const double t_gen = n * demands.generator_torque_N_m;
  double s_rotor = 0.0, s_generator = 0.0;
  sp.lock_torque_N_m = 0.0;
  if (held) {
    s_rotor = -sp.rotor_acceleration_rad_s2;  // the spin keeps its speed: ψ̈ = 0
    s_generator = -sp.generator_acceleration_rad_s2;
  } else if (!flexible) {
    const double j = j_h + j_g;
    const double lhs = j * (1.0 - am) - tau1;
    const double rhs = tau0 - t_gen - j * sp.rotor_acceleration_rad_s2 - (j_h + n * j_gen) * e_alpha;
    if (locked) {  // lhs s = rhs + r with s = −a0: r is the lock's torque
      s_rotor = -sp.rotor_acceleration_rad_s2;
      sp.lock_torque_N_m = lhs * s_rotor - rhs;
    } else {
      s_rotor = rhs / lhs;
    }
    s_generator = s_rotor;
  } else {
    const double k = params_.torsional_stiffness_N_m_rad, c = params_.torsional_damping_N_m_s_rad;
    const double shaft0 = k * ((1.0 - af) * (psi1 - th1) + af * (sp.rotor_azimuth_rad - sp.generator_azimuth_rad)) +
                          c * ((1.0 - af) * (psi_dot1 - th_dot1) + af * (sp.rotor_speed_rad_s - sp.generator_speed_rad_s));
    const double kappa = (1.0 - af) * (k * beta * dt * dt + c * gamma * dt);
    Eigen::Matrix2d m;
    m << j_h * (1.0 - am) - tau1 + kappa, -kappa, -kappa, j_g * (1.0 - am) + kappa;
    const Eigen::Vector2d r(tau0 - shaft0 - j_h * sp.rotor_acceleration_rad_s2 - j_h * e_alpha,
                            shaft0 - t_gen - j_g * sp.generator_acceleration_rad_s2 - n * j_gen * e_alpha);
    if (locked) {  // the generator's row takes the lock's torque; the rotor's balance holds as it is
      s_generator = -sp.generator_acceleration_rad_s2;
      s_rotor = (r[0] - m(0, 1) * s_generator) / m(0, 0);
      sp.lock_torque_N_m = m(1, 0) * s_rotor + m(1, 1) * s_generator - r[1];
    } else {
      const Eigen::Vector2d s = m.partialPivLu().solve(r);
      s_rotor = s[0];
      s_generator = s[1];
    }
  }
  if (!std::isfinite(s_rotor) || !std::isfinite(s_generator))
    throw NumericalError({"rotor", t + dt, "rotor spin acceleration", "reduce the blade time step"},
                         "non-finite rotor spin acceleration");

  // Every blade finishes or none does: all are checked before any moves.
  for (int b = 0; b < kBlades; ++b) steppers_[b]->solve(held ? 0.0 : s_rotor, d.state.blades[b]);
  for (int b = 0; b < kBlades; ++b) steppers_[b]->commit(d.state.blades[b]);

  auto integrate = [&](double& x, double& v, double& a, double& mean, double s) {
    const double a1 = a + s;
    const double v1 = v + dt * ((1.0 - gamma) * a + gamma * a1);
    x += dt * v + dt * dt * ((0.5 - beta) * a + beta * a1);
    mean = (v1 - v) / dt;
    v = v1;
    a = a1;
  };
  integrate(sp.rotor_azimuth_rad, sp.rotor_speed_rad_s, sp.rotor_acceleration_rad_s2, sp.rotor_mean_acceleration_rad_s2,
            s_rotor);
  integrate(sp.generator_azimuth_rad, sp.generator_speed_rad_s, sp.generator_acceleration_rad_s2,
            sp.generator_mean_acceleration_rad_s2, s_generator);
  d.state.time_s = t + dt;
}

void FlexibleRotor::advance(double t, double dt, const SubstepMotion<ShaftMotion>& slow, const RotorDemands& demands, Data& d,
                            RotorAero::Data* aero) {
  step(t, dt, slow.at(steppers_[0]->input_time_fraction()), demands, slow.i == 0 || params_.induction_every_small_step, d, aero);
  d.shaft = slow.at(1.0);
  d.last = root_loads(d.shaft, d.state);
}

}  // namespace fowtsim::driver
