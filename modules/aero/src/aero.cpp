#include "fowtsim/aero/aero.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>
#include <string>

#include <fmt/format.h>

#include "fowtsim/aero/tower_influence.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation.hpp"

namespace fowtsim::aero {
namespace {

constexpr double kPi = std::numbers::pi;

void require_size(bool ok, const char* what, long got, long expected) {
  if (!ok) {
    throw InputError({"aero", std::nullopt, what, "size the input with make_input(params)"},
                     fmt::format("aero input {} has size {} (expected {})", what, got, expected));
  }
}

void require_finite(bool ok, const char* what, double time_s) {
  if (!ok) {
    throw NumericalError({"aero", time_s, what, "check the module feeding this input (reduce dt?)"},
                         fmt::format("non-finite entry in aero input {}", what));
  }
}

void check_input(const Params& params, const Aero::Input& in) {
  const long n = node_count(params), b = params.number_of_blades;
  require_size(in.blade_pitch_rad.size() == b, "blade_pitch_rad", in.blade_pitch_rad.size(), b);
  require_size(in.node_position_m.cols() == n, "node_position_m", in.node_position_m.cols(), n);
  require_size(static_cast<long>(in.node_orientation.size()) == n, "node_orientation",
               static_cast<long>(in.node_orientation.size()), n);
  require_size(in.node_velocity_m_s.cols() == n, "node_velocity_m_s", in.node_velocity_m_s.cols(), n);
  require_size(in.inflow_velocity_m_s.cols() == n, "inflow_velocity_m_s", in.inflow_velocity_m_s.cols(), n);
  const double t = in.time_s;
  require_finite(in.hub_position_m.allFinite() && in.hub_orientation.allFinite(), "hub pose", t);
  require_finite(std::isfinite(in.rotor_speed_rad_s), "rotor_speed_rad_s", t);
  require_finite(in.blade_pitch_rad.allFinite(), "blade_pitch_rad", t);
  require_finite(in.node_position_m.allFinite(), "node_position_m", t);
  require_finite(in.node_velocity_m_s.allFinite(), "node_velocity_m_s", t);
  require_finite(in.inflow_velocity_m_s.allFinite(), "inflow_velocity_m_s", t);
  require_finite(in.node_pitch_rate_rad_s.allFinite(), "node_pitch_rate_rad_s", t);
  for (const Mat3& m : in.node_orientation) require_finite(m.allFinite(), "node_orientation", t);
  require_finite(in.tower_base_position_m.allFinite() && in.tower_axis.allFinite(), "tower pose", t);
}

// Exact integral over the blade of the loads linear between nodes (AeroDyn's line-to-point load
// transfer does the same): ∫ f ds and ∫ (r × f + m) ds with f, m and the position r linear on
// each element, r measured from the hub centre.
void integrate_blade(const Aero::Input& in, const Aero::Output& out, int first, int count, Vec3& force,
                     Vec3& moment) {
  for (int k = first; k + 1 < first + count; ++k) {
    const Vec3 r1 = in.node_position_m.col(k) - in.hub_position_m;
    const Vec3 r2 = in.node_position_m.col(k + 1) - in.hub_position_m;
    const double length = (r2 - r1).norm();
    const Vec3 f1 = out.force_N_m.col(k), f2 = out.force_N_m.col(k + 1);
    force += 0.5 * length * (f1 + f2);
    moment += length * (r1.cross(f1) / 3.0 + (r1.cross(f2) + r2.cross(f1)) / 6.0 + r2.cross(f2) / 3.0) +
              0.5 * length * (out.moment_N_m_m.col(k) + out.moment_N_m_m.col(k + 1));
  }
}

void set_coefficients(SectionSolution& sol, const AirfoilCoefficients& k) {
  // c_n, c_t from the velocity triangle's φ, as section_with_induction() forms them.
  const double sp = std::sin(sol.phi_rad), cp = std::cos(sol.phi_rad);
  sol.coefficients = k;
  sol.cn = k.cl * cp + k.cd * sp;
  sol.ct = k.cl * sp - k.cd * cp;
}

}  // namespace

UnsteadyAirfoilConstants unsteady_airfoil_constants(const Params& params) {
  return {params.ua_pressure_time_constant, params.ua_separation_time_constant, params.ua_cutout_rad};
}

Aero::Input make_input(const Params& params) {
  const int n = node_count(params);
  Aero::Input in;
  in.blade_pitch_rad = VecX::Zero(params.number_of_blades);
  in.node_position_m = Points::Zero(3, n);
  in.node_orientation.assign(n, Mat3::Identity());
  in.node_velocity_m_s = Points::Zero(3, n);
  in.inflow_velocity_m_s = Points::Zero(3, n);
  in.node_pitch_rate_rad_s = VecX::Zero(n);
  return in;
}

Aero::Output make_output(const Params& params) {
  const int n = node_count(params);
  Aero::Output out;
  out.force_N_m = Points::Zero(3, n);
  out.moment_N_m_m = Points::Zero(3, n);
  out.disturbed_inflow_m_s = Points::Zero(3, n);
  out.nodes.assign(n, NodeResult{});
  return out;
}

Aero::Output Aero::outputs(const Params& params, const Input& input, const State& state) {
  Output out = make_output(params);
  evaluate(params, input, state, out);
  return out;
}

void evaluate(const Params& params, const Aero::Input& in, const Aero::State& state, Aero::Output& out,
              Induction induction) {
  check_input(params, in);
  const int nb = params.number_of_blades, nn = nodes_per_blade(params), n = nb * nn;
  require_size(out.force_N_m.cols() == n && static_cast<int>(out.nodes.size()) == n, "output (make_output)",
               out.force_N_m.cols(), n);
  // The unsteady models act once their states are started (a default State is quasi-steady).
  const bool filtered = state.started && params.dynamic_inflow == DynamicInflowModel::oye;
  const bool dynamic_airfoil = state.started && params.unsteady_airfoil == UnsteadyAirfoilModel::hgm;
  if (state.started)
    require_size(static_cast<int>(state.nodes.size()) == n, "state (make_state)", static_cast<long>(state.nodes.size()), n);
  const UnsteadyAirfoilConstants ua_constants = unsteady_airfoil_constants(params);
  auto pitch_rate = [&](int i) { return in.node_pitch_rate_rad_s.size() == n ? in.node_pitch_rate_rad_s(i) : 0.0; };
  double induction_sum = 0.0;
  int induction_count = 0;
  const Vec3 x_h = in.hub_orientation.col(0);

  // Disk-mean relative inflow: reference speed of the coefficients and direction of the skew.
  Vec3 mean = Vec3::Zero();
  double radius = 0.0;
  for (int i = 0; i < n; ++i) {
    mean += in.inflow_velocity_m_s.col(i) - in.node_velocity_m_s.col(i);
    const Vec3 rel = in.node_position_m.col(i) - in.hub_position_m;
    radius = std::max(radius, (rel - rel.dot(x_h) * x_h).norm());
  }
  mean /= n;
  const double u_axial = mean.dot(x_h);
  const Vec3 in_plane = mean - u_axial * x_h;
  const double skew = std::atan2(in_plane.norm(), u_axial);
  const bool redistribute = params.skew_model == SkewModel::pitt_peters && in_plane.norm() > 1e-12 &&
                            skew < 0.5 * kPi && radius > 0.0;
  const Vec3 downwind = redistribute ? Vec3(in_plane.normalized()) : Vec3::Zero();

  out.unconverged_nodes = 0;
  // Loads per unit span of node i from its section solution.
  auto store = [&](int i, const Mat3& t_gb, const SectionInflow& s, const SectionSolution& sol) {
    const BladeNodeParams& node = params.blade[i % nn];
    if (sol.status == InductionStatus::no_root) ++out.unconverged_nodes;
    const double q = 0.5 * params.air_density_kg_m3 * sol.relative_speed_m_s * sol.relative_speed_m_s;
    NodeResult& r = out.nodes[i];
    r.section = sol;
    r.local_radius_m = s.local_radius_m;
    r.axial_velocity_m_s = s.axial_velocity_m_s;
    r.tangential_velocity_m_s = s.tangential_velocity_m_s;
    r.normal_force_N_m = q * node.chord_m * sol.cn;
    r.tangential_force_N_m = q * node.chord_m * sol.ct;
    out.force_N_m.col(i) = t_gb * Vec3(r.normal_force_N_m, -r.tangential_force_N_m, 0.0);
    const double cm = params.pitching_moment ? sol.coefficients.cm : 0.0;
    out.moment_N_m_m.col(i) = t_gb.col(2) * (q * node.chord_m * node.chord_m * cm);
  };
  for (int blade = 0; blade < nb; ++blade) {
    const int first = blade * nn;
    auto radial = [&](int i) {
      const Vec3 rel = in.node_position_m.col(i) - in.hub_position_m;
      return Vec3(rel - rel.dot(x_h) * x_h);
    };
    const double hub_radius = radial(first).norm(), tip_radius = radial(first + nn - 1).norm();
    for (int k = 0; k < nn; ++k) {
      const int i = first + k;
      const BladeNodeParams& node = params.blade[k];
      const Polar& polar = params.airfoils[node.airfoil];
      const Vec3 disturbance = tower_disturbance(params, in.tower_base_position_m, in.tower_axis,
                                                 in.node_position_m.col(i), in.inflow_velocity_m_s.col(i));
      out.disturbed_inflow_m_s.col(i) = in.inflow_velocity_m_s.col(i) + disturbance;
      const Vec3 relative = out.disturbed_inflow_m_s.col(i) - in.node_velocity_m_s.col(i);
      const double theta = node.twist_rad + in.blade_pitch_rad(blade);
      // cos θ, sin θ of the last evaluation on this Output while θ is the same (the pitch moves at
      // the large step, the held evaluations of the small steps reuse them): the bits of rotation_z.
      NodeResult& cached = out.nodes[i];
      if (theta != cached.theta_rad) {
        cached.theta_rad = theta;
        cached.cos_theta = std::cos(theta);
        cached.sin_theta = std::sin(theta);
      }
      Mat3 rotation_theta;
      rotation_theta << cached.cos_theta, -cached.sin_theta, 0.0, cached.sin_theta, cached.cos_theta, 0.0, 0.0, 0.0, 1.0;
      const Mat3 t_gb = in.node_orientation[i] * rotation_theta;
      const Vec3 r_vec = radial(i);
      SectionInflow s;
      s.axial_velocity_m_s = relative.dot(t_gb.col(0));
      s.tangential_velocity_m_s = relative.dot(t_gb.col(1));
      s.local_radius_m = r_vec.norm();
      s.hub_radius_m = hub_radius;
      s.tip_radius_m = tip_radius;
      s.chord_m = node.chord_m;
      s.theta_rad = theta;
      s.number_of_blades = nb;
      const NodeResult& last = out.nodes[i];
      const SectionSolution& previous = last.section;
      const bool moving = std::abs(s.axial_velocity_m_s) > 1e-6 && std::abs(s.tangential_velocity_m_s) > 1e-6;
      const bool hold = induction == Induction::held && previous.status == InductionStatus::converged && moving;
      SectionSolution sol;
      double qs_axial = 0.0, qs_tangential = 0.0;  // quasi-steady a V_x, a' V_y
      if (hold && filtered) {
        // The filters replace the induction below; the quasi-steady input stays that of the last solve.
        sol = previous;
        qs_axial = last.quasi_steady_axial_induced_m_s;
        qs_tangential = last.quasi_steady_tangential_induced_m_s;
      } else if (hold) {
        // A frozen wake: the induced velocities a V_x and a' V_y of the last solve (skew
        // redistribution included) are held and the section's own motion enters the relative
        // velocity in full. Holding the factors a, a' instead would scale the blade's velocity by
        // (1 − a) and flip its aerodynamic damping wherever a > 1 (measured: a blade released from
        // its centrifugal shape into 12 m/s flutters within 0.3 s). The products stay those of the
        // last solve through any number of held calls.
        const double a = previous.axial_induction * last.axial_velocity_m_s / s.axial_velocity_m_s;
        const double ap = previous.tangential_induction * last.tangential_velocity_m_s / s.tangential_velocity_m_s;
        sol = section_with_induction(s, polar, a, ap, previous);
        qs_axial = a * s.axial_velocity_m_s;
        qs_tangential = ap * s.tangential_velocity_m_s;
      } else {
        // Warm start from this node's root of the previous evaluation on the same Output.
        sol = solve_section(s, polar, params, previous.root_phi_c_rad, previous.root_slope_per_rad);
        if (redistribute && sol.status == InductionStatus::converged) {
          // Glauert/Pitt–Peters: a_skew = a [1 + K (r/R) tan(χ/2) cos ψ], ψ measured from the
          // downwind side of the disk (where the in-plane inflow points), wake skew χ = (0.6 a + 1) χ0
          // (Burton et al. 2011, Wind Energy Handbook §3.10), χ capped at 90°.
          const double chi = std::min((0.6 * sol.axial_induction + 1.0) * skew, 0.5 * kPi);
          const double cos_psi = s.local_radius_m > 0.0 ? r_vec.dot(downwind) / s.local_radius_m : 0.0;
          const double factor = 1.0 + params.skew_factor * (s.local_radius_m / radius) * std::tan(0.5 * chi) * cos_psi;
          sol = section_with_induction(s, polar, sol.axial_induction * factor, sol.tangential_induction, sol);
        }
        qs_axial = sol.axial_induction * s.axial_velocity_m_s;
        qs_tangential = sol.tangential_induction * s.tangential_velocity_m_s;
      }
      if (sol.status == InductionStatus::converged && moving) {
        induction_sum += qs_axial / s.axial_velocity_m_s;
        ++induction_count;
      }
      if (filtered && moving) {
        // Dynamic inflow: the filtered induced velocities replace the quasi-steady ones.
        const NodeUnsteadyState& u = state.nodes[i];
        sol = section_with_induction(s, polar, u.axial.w / s.axial_velocity_m_s,
                                     u.tangential.w / s.tangential_velocity_m_s, sol);
      }
      if (dynamic_airfoil) {
        const SectionMotion m{sol.alpha_rad, sol.relative_speed_m_s, pitch_rate(i), node.chord_m};
        set_coefficients(sol, unsteady_coefficients(polar, polar.separation(), ua_constants, m, state.nodes[i].airfoil));
      }
      store(i, t_gb, s, sol);
      NodeResult& r = out.nodes[i];
      r.theta_rad = theta;
      r.quasi_steady_axial_induced_m_s = qs_axial;
      r.quasi_steady_tangential_induced_m_s = qs_tangential;
    }
  }

  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
  for (int blade = 0; blade < nb; ++blade) integrate_blade(in, out, blade * nn, nn, force, moment);
  RotorResult& rotor = out.rotor;
  rotor.force_hub_N = in.hub_orientation.transpose() * force;
  rotor.moment_hub_N_m = in.hub_orientation.transpose() * moment;
  rotor.power_W = in.rotor_speed_rad_s * rotor.moment_hub_N_m.x();
  rotor.mean_axial_inflow_m_s = u_axial;
  rotor.mean_quasi_steady_axial_induction = induction_count > 0 ? induction_sum / induction_count : 0.0;
  rotor.skew_rad = skew;
  rotor.radius_m = radius;
  rotor.area_m2 = kPi * radius * radius;
  if (std::abs(u_axial) >= 1e-6 && radius > 0.0) {
    const double q_disk = 0.5 * params.air_density_kg_m3 * rotor.area_m2 * u_axial * u_axial;
    rotor.tip_speed_ratio = in.rotor_speed_rad_s * radius / u_axial;
    rotor.cp = rotor.power_W / (q_disk * u_axial);
    rotor.ct = rotor.force_hub_N.x() / q_disk;
    rotor.cq = rotor.moment_hub_N_m.x() / (q_disk * radius);
  } else {
    rotor.tip_speed_ratio = rotor.cp = rotor.ct = rotor.cq = 0.0;
  }
  if (!force.allFinite() || !moment.allFinite() || !std::isfinite(rotor.cp)) {
    throw NumericalError({"aero", in.time_s, "rotor loads", "check the node motion handed to the aero module"},
                         "non-finite rotor aerodynamic loads");
  }
}

}  // namespace fowtsim::aero
