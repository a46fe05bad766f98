// The rotor's unsteady states (aero.hpp): started from, and advanced with, evaluations of the rotor.
#include <algorithm>
#include <cmath>

#include "fowtsim/aero/aero.hpp"

namespace fowtsim::aero {
namespace {

bool moving(const NodeResult& r) {
  return std::abs(r.axial_velocity_m_s) > 1e-6 && std::abs(r.tangential_velocity_m_s) > 1e-6;
}

// Øye's τ1 from an evaluation; 0 when the disk has no inflow to scale it (the filters then follow
// the quasi-steady induction).
double tau1_of(const RotorResult& rotor) {
  if (!(rotor.mean_axial_inflow_m_s > 0.1) || !(rotor.radius_m > 0.0)) return 0.0;
  return oye_tau1(rotor.mean_quasi_steady_axial_induction, rotor.radius_m, rotor.mean_axial_inflow_m_s);
}

const Polar& polar_of(const Params& params, int i) {
  const BladeNodeParams& node = params.blade[static_cast<std::size_t>(i % nodes_per_blade(params))];
  return params.airfoils[static_cast<std::size_t>(node.airfoil)];
}

SectionMotion motion_of(const Params& params, const Aero::Input& in, int i, double alpha,
                        double speed) {
  const double rate = in.node_pitch_rate_rad_s.size() == node_count(params) ? in.node_pitch_rate_rad_s(i) : 0.0;
  return {alpha, speed, rate, params.blade[static_cast<std::size_t>(i % nodes_per_blade(params))].chord_m};
}

}  // namespace

Aero::State Aero::make_state(const Params& params) {
  State s;
  if (has_unsteady_models(params)) s.nodes.assign(static_cast<std::size_t>(node_count(params)), NodeUnsteadyState{});
  return s;
}

void Aero::advance(const Params& params, const Input& input_at_end, double t, double dt, State& state) {
  if (!has_unsteady_models(params)) return;
  if (!state.started) state.time_s = t;
  Output at_end = make_output(params);
  evaluate(params, input_at_end, state, at_end);
  advance_states(params, input_at_end, at_end, dt, state);
}

void start_states(const Params& params, const Aero::Input& in, const Aero::Output& at, double t, Aero::State& state) {
  const int n = node_count(params);
  if (static_cast<int>(state.nodes.size()) != n) state.nodes.assign(static_cast<std::size_t>(n), NodeUnsteadyState{});
  const UnsteadyAirfoilConstants k = unsteady_airfoil_constants(params);
  for (int i = 0; i < n; ++i) {
    const NodeResult& r = at.nodes[static_cast<std::size_t>(i)];
    NodeUnsteadyState& u = state.nodes[static_cast<std::size_t>(i)];
    u.quasi_steady_axial_m_s = r.quasi_steady_axial_induced_m_s;
    u.quasi_steady_tangential_m_s = r.quasi_steady_tangential_induced_m_s;
    u.axial = oye_steady(u.quasi_steady_axial_m_s);
    u.tangential = oye_steady(u.quasi_steady_tangential_m_s);
    // α and W with the (steady) filtered induction = the quasi-steady section of the evaluation.
    double alpha = r.section.alpha_rad, speed = r.section.relative_speed_m_s;
    if (params.dynamic_inflow == DynamicInflowModel::oye && moving(r)) {
      const double ux = r.axial_velocity_m_s - u.axial.w, uy = r.tangential_velocity_m_s + u.tangential.w;
      alpha = wrap_angle(std::atan2(ux, uy) - r.theta_rad);
      speed = std::hypot(ux, uy);
    }
    const Polar& polar = polar_of(params, i);
    u.airfoil = unsteady_airfoil_steady(polar, polar.separation(), k, motion_of(params, in, i, alpha, speed));
  }
  state.tau1_s = tau1_of(at.rotor);
  state.time_s = t;
  state.started = true;
}

void advance_states(const Params& params, const Aero::Input& in, const Aero::Output& at_end, double dt,
                    Aero::State& state) {
  if (!state.started) {
    start_states(params, in, at_end, state.time_s + dt, state);
    return;
  }
  if (!(dt > 0.0)) return;  // nothing to integrate
  const int n = node_count(params);
  const bool oye = params.dynamic_inflow == DynamicInflowModel::oye;
  const bool hgm = params.unsteady_airfoil == UnsteadyAirfoilModel::hgm;
  const UnsteadyAirfoilConstants k = unsteady_airfoil_constants(params);
  const double tau1_end = tau1_of(at_end.rotor);
  // τ1 over the step: the mean of its ends (the disk's ā and Ū change slowly); no inflow at either
  // end → the filters take the quasi-steady induction.
  const double tau1 = state.tau1_s > 0.0 && tau1_end > 0.0 ? 0.5 * (state.tau1_s + tau1_end) : 0.0;
  const double radius = at_end.rotor.radius_m;
  for (int i = 0; i < n; ++i) {
    const NodeResult& r = at_end.nodes[static_cast<std::size_t>(i)];
    NodeUnsteadyState& u = state.nodes[static_cast<std::size_t>(i)];
    const double qa = r.quasi_steady_axial_induced_m_s, qt = r.quasi_steady_tangential_induced_m_s;
    double alpha = r.section.alpha_rad, speed = r.section.relative_speed_m_s;
    if (oye) {
      if (tau1 > 0.0) {
        const double tau2 = oye_tau2(tau1, std::min(r.local_radius_m / radius, 1.0));
        advance_oye(u.axial, tau1, tau2, u.quasi_steady_axial_m_s, qa, dt);
        advance_oye(u.tangential, tau1, tau2, u.quasi_steady_tangential_m_s, qt, dt);
      } else {
        u.axial = oye_steady(qa);
        u.tangential = oye_steady(qt);
      }
      if (moving(r)) {
        // α, W at the step's end with the filtered induction of the step's end.
        const double ux = r.axial_velocity_m_s - u.axial.w, uy = r.tangential_velocity_m_s + u.tangential.w;
        alpha = wrap_angle(std::atan2(ux, uy) - r.theta_rad);
        speed = std::hypot(ux, uy);
      }
    }
    u.quasi_steady_axial_m_s = qa;
    u.quasi_steady_tangential_m_s = qt;
    if (hgm) {
      const Polar& polar = polar_of(params, i);
      advance_unsteady_airfoil(polar, polar.separation(), k, motion_of(params, in, i, alpha, speed), dt, u.airfoil);
    }
  }
  state.tau1_s = tau1_end;
  state.time_s += dt;
}

}  // namespace fowtsim::aero
