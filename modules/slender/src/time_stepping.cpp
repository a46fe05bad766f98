#include "fowtsim/slender/time_stepping.hpp"

#include <string>
#include <utility>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/slender/bending_moment.hpp"

namespace fowtsim::slender {
namespace {

using Params = SlenderBody::Params;
using Workspace = SlenderBody::Workspace;

// Morison force per length f at the strips (into work.force) for the kinematics in column c and
// the strip velocities work.strip_velocity; work.weighted = f Δx.
void strip_force(const Params& p, const SlenderBody::Input& in, Eigen::Index c, Workspace& w) {
  const StripTable& s = p.model.strips;
  w.relative = in.velocity_m_s.col(c) - w.strip_velocity;
  w.force = s.inertia_coefficient_kg_m.cwiseProduct(in.acceleration_m_s2.col(c)) +
            s.drag_factor_kg_m2.cwiseProduct(w.relative.cwiseAbs().cwiseProduct(w.relative));
  w.weighted = w.force.cwiseProduct(s.dx_m);
}

// ä = Q_b − C_b ȧ − Ω² a (into out) for the force in work.weighted.
void modal_acceleration(const Params& p, const VecX& a, const VecX& a_dot, Workspace& w, VecX& out) {
  w.modal_force.noalias() = p.strip_modes.transpose() * w.weighted;
  w.damping_force.noalias() = p.modal_damping * a_dot;
  out = w.modal_force - w.damping_force - p.omega2.cwiseProduct(a);
}

// The derivative of z = [a; ȧ] at kinematics column c: (ȧ, ä) into (da, dv).
void derivative(const Params& p, const SlenderBody::Input& in, Eigen::Index c, const VecX& a, const VecX& a_dot, Workspace& w,
                VecX& da, VecX& dv) {
  w.strip_velocity.noalias() = p.strip_modes * a_dot;
  strip_force(p, in, c, w);
  modal_acceleration(p, a, a_dot, w, dv);
  da = a_dot;
}

}  // namespace

SlenderBody::Params make_time_domain_params(const Model& model, const Modes& modes, Recovery recovery) {
  const MatX& Psi = modes.shapes;
  Params p{model, modes, model.phi * Psi, Psi.transpose() * model.structural_damping * Psi, modes.omega_rad_s.cwiseAbs2(),
           recovery == Recovery::ModeAcceleration && Psi.cols() < model.mass.rows(), {}};
  if (p.mode_acceleration) {
    p.stiffness.compute(model.stiffness);
    if (p.stiffness.info() != Eigen::Success)
      throw InputError({"slender.time_domain", std::nullopt, "K", "add end springs or keep every mode"},
                       "mode acceleration needs K positive definite");
  }
  return p;
}

SlenderBody::Input make_input(const Params& p) {
  const auto N = p.model.strips.x_m.size();
  return {MatX::Zero(N, 3), MatX::Zero(N, 3)};
}

SlenderBody::Output make_output(const Params& p) {
  const auto N = p.model.strips.x_m.size(), n = p.model.mass.rows();
  return {VecX::Zero(n), VecX::Zero(N), VecX::Zero(N), VecX::Zero(N)};
}

SlenderBody::Workspace make_workspace(const Params& p) {
  const auto N = p.model.strips.x_m.size(), n = p.model.mass.rows(), z = p.modes.shapes.cols();
  const VecX strips = VecX::Zero(N), modal = VecX::Zero(z), generalised = VecX::Zero(n);
  return {strips, strips, strips, strips, strips, strips, strips,
          modal,  modal,  modal,  modal,  modal,  modal,  modal,  modal,
          modal,  modal,  modal,  modal,  modal,  modal,  modal,  modal,
          generalised, generalised, generalised, generalised, generalised};
}

SlenderBody::State SlenderBody::make_state(const Params& p) {
  const auto z = p.modes.shapes.cols();
  return {0, VecX::Zero(z), VecX::Zero(z)};
}

void SlenderBody::advance(const Params& p, const Input& in, double t, double dt, State& s, Workspace& w) {
  // Classical RK4 (core/rk4.hpp's arithmetic, term by term, on workspace vectors); the waves at
  // the step's start, midpoint (both middle stages) and end.
  derivative(p, in, 0, s.a, s.a_dot, w, w.k1a, w.k1v);
  w.stage_a = s.a + 0.5 * dt * w.k1a;
  w.stage_v = s.a_dot + 0.5 * dt * w.k1v;
  derivative(p, in, 1, w.stage_a, w.stage_v, w, w.k2a, w.k2v);
  w.stage_a = s.a + 0.5 * dt * w.k2a;
  w.stage_v = s.a_dot + 0.5 * dt * w.k2v;
  derivative(p, in, 1, w.stage_a, w.stage_v, w, w.k3a, w.k3v);
  w.stage_a = s.a + dt * w.k3a;
  w.stage_v = s.a_dot + dt * w.k3v;
  derivative(p, in, 2, w.stage_a, w.stage_v, w, w.k4a, w.k4v);
  w.next_a = s.a + (dt / 6.0) * (w.k1a + 2.0 * w.k2a + 2.0 * w.k3a + w.k4a);
  w.next_v = s.a_dot + (dt / 6.0) * (w.k1v + 2.0 * w.k2v + 2.0 * w.k3v + w.k4v);
  if (!w.next_a.allFinite() || !w.next_v.allFinite())  // atomic: the state stays at t
    throw NumericalError({"slender.time_domain", t + dt, "modal state z", "reduce the time step"}, "non-finite modal state");
  s.a.swap(w.next_a);  // swaps the buffers: no allocation
  s.a_dot.swap(w.next_v);
  ++s.step;
}

void SlenderBody::advance(const Params& p, const Input& in, double t, double dt, State& s) {
  Workspace w = make_workspace(p);
  advance(p, in, t, dt, s, w);
}

void SlenderBody::outputs(const Params& p, const Input& in, const State& s, Workspace& w, Output& out) {
  const Model& m = p.model;
  const MatX& Psi = p.modes.shapes;
  w.strip_velocity.noalias() = p.strip_modes * s.a_dot;
  strip_force(p, in, 0, w);
  modal_acceleration(p, s.a, s.a_dot, w, w.a_ddot);
  if (p.mode_acceleration) {  // slide "Solution in Time Domain": q = K⁻¹[Q − MΨä − CΨȧ]
    w.generalised_force.noalias() = m.phi.transpose() * w.weighted;
    w.q_modal.noalias() = Psi * w.a_ddot;
    w.mass_force.noalias() = m.mass * w.q_modal;
    w.q_modal.noalias() = Psi * s.a_dot;
    w.damping_force_n.noalias() = m.structural_damping * w.q_modal;
    out.q = w.generalised_force - w.mass_force - w.damping_force_n;
    p.stiffness.solveInPlace(out.q);
  } else {
    out.q.noalias() = Psi * s.a;
  }
  // Load per length on the deflected body: wave force − inertia − mass-proportional damping.
  w.strip_acceleration.noalias() = p.strip_modes * w.a_ddot;
  w.load = w.force - m.strips.mass_kg_m.cwiseProduct(w.strip_acceleration + m.body.rayleigh_mass_per_s * w.strip_velocity);
  out.displacement_m.noalias() = m.phi * out.q;
  elastic_moment_into(m, out.q, w.slope, out.moment_elastic_N_m);
  w.inertial_modal = w.a_ddot + m.body.rayleigh_mass_per_s * s.a_dot;  // q̈ + α q̇ for the point masses
  w.inertial_q.noalias() = Psi * w.inertial_modal;
  w.slope.noalias() = m.phi_slope * out.q;
  inertia_relief_moment_into(m, w.load, w.slope, out.q, w.inertial_q, out.moment_inertia_relief_N_m);
}

SlenderBody::Output SlenderBody::outputs(const Params& p, const Input& in, const State& s) {
  Workspace w = make_workspace(p);
  Output out = make_output(p);
  outputs(p, in, s, w, out);
  return out;
}

std::vector<ChannelInfo> SlenderBody::channels(const Params& p) {
  std::vector<ChannelInfo> all;
  for (Eigen::Index i = 0; i < p.model.strips.x_m.size(); ++i) {
    const std::string at = fmt::format("at strip {} (midpoint x = {:.6g} m from the bottom end)", i + 1, p.model.strips.x_m(i));
    all.push_back({fmt::format("Strip{}Disp", i + 1), "m", "transverse displacement " + at, "slender"});
    all.push_back({fmt::format("Strip{}MomEI", i + 1), "N-m", "bending moment EI v'' " + at, "slender"});
    all.push_back({fmt::format("Strip{}MomIR", i + 1), "N-m", "bending moment by inertia relief " + at, "slender"});
  }
  return all;
}

}  // namespace fowtsim::slender
