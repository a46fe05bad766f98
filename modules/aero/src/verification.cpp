#include "fowtsim/aero/verification.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "fowtsim/aero/aero.hpp"
#include "fowtsim/aero/bem.hpp"
#include "fowtsim/aero/tower_influence.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::aero::verification {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

}  // namespace

RigidRotor nrel5mw_rigid_rotor() {
  const double tilt = 5.0 * kDegree, overhang = 5.0191;
  return {Vec3(-overhang * std::cos(tilt), 0.0, 87.6 + 1.96256 + overhang * std::sin(tilt)), 0.0, tilt, 2.5 * kDegree, 1.5};
}

CpPeak peak_power_coefficient(const Params& params, const RigidRotor& rotor, double wind_m_s) {
  Aero::Input in = make_input(params);
  Aero::Output out = make_output(params);
  in.inflow_velocity_m_s.colwise() = Vec3(wind_m_s, 0.0, 0.0);
  // One evaluation for the disk-mean inflow and radius that define λ (RtTSR).
  place_rigid_rotor(params, rotor, 0.0, 1.0, 0.0, in);
  evaluate(params, in, Aero::State{}, out);
  const double radius = out.rotor.radius_m, u = out.rotor.mean_axial_inflow_m_s;
  std::vector<double> lambda, cp;
  for (double l = 5.0; l <= 11.0 + 1e-9; l += 0.05) {
    double mean = 0.0;
    constexpr int kAzimuths = 12;  // over one 120° period of the three-bladed rotor
    for (int k = 0; k < kAzimuths; ++k) {
      place_rigid_rotor(params, rotor, 2.0 * std::numbers::pi / 3.0 * k / kAzimuths, l * u / radius, 0.0, in);
      evaluate(params, in, Aero::State{}, out);
      mean += out.rotor.cp / kAzimuths;
    }
    lambda.push_back(l);
    cp.push_back(mean);
  }
  const std::size_t best = static_cast<std::size_t>(std::max_element(cp.begin(), cp.end()) - cp.begin());
  if (best == 0 || best + 1 == cp.size()) {
    throw NumericalError({"aero.verification", std::nullopt, "Cp–λ peak", "widen the λ sweep"},
                         "the Cp–λ curve peaks at an end of λ = 5…11");
  }
  // Vertex of the parabola through the best sample and its neighbours (equal spacing h).
  const double h = lambda[1] - lambda[0];
  const double c0 = cp[best - 1], c1 = cp[best], c2 = cp[best + 1];
  const double shift = 0.5 * h * (c0 - c2) / (c0 - 2.0 * c1 + c2);
  return {c1 - 0.25 * (c0 - c2) * shift / h, lambda[best] + shift};
}

RotorMean rotor_mean(const Params& params, const RigidRotor& rotor, double wind_m_s, double rotor_speed_rpm,
                     double pitch_deg, const std::vector<double>& azimuth_deg) {
  if (azimuth_deg.empty()) {
    throw InputError({"aero.verification", std::nullopt, "azimuths", "give at least one azimuth"},
                     "a rotor mean needs at least one azimuth");
  }
  Aero::Input in = make_input(params);
  Aero::Output out = make_output(params);
  in.inflow_velocity_m_s.colwise() = Vec3(wind_m_s, 0.0, 0.0);
  RotorMean m;
  m.alpha_deg.assign(params.output_nodes.size(), 0.0);
  m.axial_induction.assign(params.output_nodes.size(), 0.0);
  for (const ChannelInfo& c : Aero::channels(params)) m.channel_names.push_back(c.name);
  m.channel_means.assign(m.channel_names.size(), 0.0);
  std::vector<double> values(m.channel_names.size());
  const double n = static_cast<double>(azimuth_deg.size());
  for (double azimuth : azimuth_deg) {
    place_rigid_rotor(params, rotor, azimuth * kDegree, rotor_speed_rpm * std::numbers::pi / 30.0, pitch_deg * kDegree, in);
    evaluate(params, in, Aero::State{}, out);
    if (out.unconverged_nodes != 0) ++m.unconverged_evaluations;
    m.power_W += out.rotor.power_W / n;
    m.thrust_N += out.rotor.force_hub_N.x() / n;
    m.torque_N_m += out.rotor.moment_hub_N_m.x() / n;
    m.cp += out.rotor.cp / n;
    m.ct += out.rotor.ct / n;
    for (std::size_t j = 0; j < params.output_nodes.size(); ++j) {
      const NodeResult& node = out.nodes[params.output_nodes[j] - 1];  // blade 1
      m.alpha_deg[j] += node.section.alpha_rad / kDegree / n;
      m.axial_induction[j] += node.section.axial_induction / n;
    }
    channel_values(params, in, out, values);
    for (std::size_t k = 0; k < values.size(); ++k) m.channel_means[k] += values[k] / n;
  }
  return m;
}

double RotorMean::channel(const std::string& name) const {
  const auto it = std::find(channel_names.begin(), channel_names.end(), name);
  if (it == channel_names.end()) {
    throw InputError({"aero.verification", std::nullopt, "channel", "name a channel of Aero::channels"},
                     "the aero module writes no channel " + name);
  }
  return channel_means[static_cast<std::size_t>(it - channel_names.begin())];
}

MomentumBalance momentum_balance(Params params) {
  params.drag_in_axial_induction = params.drag_in_tangential_induction = true;
  const double rho = params.air_density_kg_m3, wind = 10.0, hub_radius = 1.5, tip_radius = 63.0;
  MomentumBalance b;
  for (double tsr : {4.0, 6.0, 8.0, 10.0}) {
    for (std::size_t k = 4; k + 1 < params.blade.size(); ++k) {
      const BladeNodeParams& node = params.blade[k];
      SectionInflow s;
      s.axial_velocity_m_s = wind;
      s.local_radius_m = hub_radius + node.span_m;
      s.tangential_velocity_m_s = tsr * wind * s.local_radius_m / tip_radius;
      s.hub_radius_m = hub_radius;
      s.tip_radius_m = tip_radius;
      s.chord_m = node.chord_m;
      s.theta_rad = node.twist_rad;
      s.number_of_blades = params.number_of_blades;
      const SectionSolution sol = solve_section(s, params.airfoils[node.airfoil], params);
      if (sol.status != InductionStatus::converged) {
        ++b.failed;
        continue;
      }
      if (sol.axial_induction > 0.4) continue;  // Buhl's branch
      const double q = 0.5 * rho * sol.relative_speed_m_s * sol.relative_speed_m_s;
      const double blade_thrust = params.number_of_blades * q * s.chord_m * sol.cn;
      const double momentum_thrust = 4.0 * std::numbers::pi * s.local_radius_m * rho * wind * wind * sol.loss_factor *
                                     sol.axial_induction * (1.0 - sol.axial_induction);
      const double blade_torque = params.number_of_blades * q * s.chord_m * sol.ct;
      const double momentum_torque = 4.0 * std::numbers::pi * s.local_radius_m * rho * wind * s.tangential_velocity_m_s *
                                     sol.loss_factor * sol.tangential_induction * (1.0 - sol.axial_induction);
      b.worst_thrust = std::max(b.worst_thrust, std::abs(blade_thrust / momentum_thrust - 1.0));
      b.worst_torque = std::max(b.worst_torque, std::abs(blade_torque / momentum_torque - 1.0));
      ++b.sections;
    }
  }
  return b;
}

PotentialFlowCheck tower_potential_flow() {
  Params p;
  p.tower_potential = TowerPotential::baseline;
  p.tower_shadow = TowerShadow::none;
  p.tower = {{0.0, 6.0, 1.0, 0.1}, {100.0, 6.0, 1.0, 0.1}};  // elevation, D = 6 m, C_d, TI
  const double u_inf = 10.0, radius = 3.0;
  const Vec3 wind(u_inf, 0.0, 0.0);
  PotentialFlowCheck c;
  for (double r_over_r : {1.1, 1.5, 2.0, 4.0, 10.0}) {
    for (int k = 0; k < 24; ++k) {
      const double angle = 2.0 * std::numbers::pi * (k + 0.5) / 24.0;
      const std::complex<double> z = r_over_r * radius * std::polar(1.0, angle);
      const std::complex<double> conj_velocity = u_inf * (1.0 - radius * radius / (z * z));
      const Vec3 v = wind + tower_disturbance(p, Vec3::Zero(), Vec3::UnitZ(), Vec3(z.real(), z.imag(), 50.0), wind);
      c.worst_m_s = std::max(c.worst_m_s, (v - Vec3(conj_velocity.real(), -conj_velocity.imag(), 0.0)).norm());
      ++c.points;
    }
  }
  return c;
}

}  // namespace fowtsim::aero::verification
