#include "fowtsim/flexbody/prebent_spinning_beam.hpp"

#include <cmath>
#include <numbers>

#include "fowtsim/core/error.hpp"
#include "fowtsim/flexbody/axial_force.hpp"
#include "fowtsim/flexbody/sampled_response.hpp"
#include "fowtsim/flexbody/shape_functions.hpp"
#include "fowtsim/flexbody/stations.hpp"
#include "fowtsim/flexbody/torsion.hpp"

namespace fowtsim::flexbody {

PrebentSpinningBeam::PrebentSpinningBeam(const PrebentBeam& beam, int n_edge, int n_flap, int n_torsion,
                                         const QuadratureRule& rule)
    : prebend_tip_(beam.prebend_tip) {
  if (n_edge < 1 || n_flap < 1 || n_torsion < 1)
    throw InputError({"flexbody", std::nullopt, "pre-bent beam shapes", "at least one edge, flap and torsion shape"},
                     "bad shape counts");
  const double L = beam.length, m = beam.mass_per_length, ei = beam.bending_stiffness;
  const double jg = beam.polar_inertia, gk = beam.torsion_stiffness;
  const BeamStations stations = uniform_beam(L, m, ei);
  const AxialForce t_hat = centrifugal_axial_force(stations, 1.0, 0.0);  // T̂ = T/Ω²
  std::vector<ShapeFunction> bend, twist;
  for (int j = 1; j <= std::max(n_edge, n_flap); ++j) bend.push_back(clamped_free_mode(j, L));
  for (int j = 1; j <= n_torsion; ++j) twist.push_back(torsion_sine_shape(j, L));

  const int n = n_edge + n_flap + n_torsion, f0 = n_edge, t0 = n_edge + n_flap;
  const auto zero = [n] { return Eigen::MatrixXd::Zero(n, n); };
  mass_ = zero(), stiffness_ = zero(), centrifugal_ = zero(), softening_ = zero(), gyroscopic_ = zero(),
  alpha_coupling_ = zero();
  euler_load_ = Eigen::VectorXd::Zero(n), prebend_load_ = Eigen::VectorXd::Zero(n);
  const double k = std::numbers::pi / (2.0 * L);
  for (const QuadraturePoint& p : quadrature_points(stations, rule)) {
    const double w = p.w, x = p.x, th = t_hat(x);
    const double dz0 = beam.prebend_tip * k * std::sin(k * x), c = beam.prebend_tip * k * k * std::cos(k * x);
    std::vector<ShapeValue> b(bend.size()), v(twist.size());
    for (std::size_t j = 0; j < bend.size(); ++j) b[j] = bend[j](x);
    for (std::size_t j = 0; j < twist.size(); ++j) v[j] = twist[j](x);
    for (int i = 0; i < n_edge; ++i) {
      for (int j = 0; j < n_edge; ++j) {
        mass_(i, j) += w * m * b[i].u * b[j].u;
        stiffness_(i, j) += w * (ei * b[i].kappa * b[j].kappa + gk * c * c * b[i].nu * b[j].nu);
        centrifugal_(i, j) += w * th * b[i].nu * b[j].nu;
        softening_(i, j) += w * m * b[i].u * b[j].u;
      }
      for (int j = 0; j < n_torsion; ++j) {  // κ_edge = u_y'' + cφ, κ_x = φ' − c u_y'
        const double kc = w * (ei * c * b[i].kappa * v[j].u - gk * c * b[i].nu * v[j].nu);
        stiffness_(i, t0 + j) += kc;
        stiffness_(t0 + j, i) += kc;
      }
      euler_load_(i) += w * m * x * b[i].u;
    }
    for (int i = 0; i < n_flap; ++i) {
      for (int j = 0; j < n_flap; ++j) {
        mass_(f0 + i, f0 + j) += w * m * b[i].u * b[j].u;
        stiffness_(f0 + i, f0 + j) += w * ei * b[i].kappa * b[j].kappa;
        centrifugal_(f0 + i, f0 + j) += w * th * b[i].nu * b[j].nu;
        softening_(f0 + i, f0 + j) += w * jg * b[i].nu * b[j].nu;
      }
      for (int j = 0; j < n_torsion; ++j) {  // j_G (φ̇ + Ω(z₀' + u_z')): gyroscopic and α terms
        gyroscopic_(t0 + j, f0 + i) += w * jg * v[j].u * b[i].nu;
        gyroscopic_(f0 + i, t0 + j) -= w * jg * v[j].u * b[i].nu;
        alpha_coupling_(t0 + j, f0 + i) += w * jg * v[j].u * b[i].nu;
      }
      prebend_load_(f0 + i) -= w * (th - jg) * dz0 * b[i].nu;
    }
    for (int i = 0; i < n_torsion; ++i) {
      for (int j = 0; j < n_torsion; ++j) {
        mass_(t0 + i, t0 + j) += w * jg * v[i].u * v[j].u;
        stiffness_(t0 + i, t0 + j) += w * (gk * v[i].nu * v[j].nu + ei * c * c * v[i].u * v[j].u);
      }
      euler_load_(t0 + i) += w * jg * dz0 * v[i].u;
    }
  }
  edge_tip_ = flap_tip_ = torsion_tip_ = Eigen::VectorXd::Zero(n);
  for (int j = 0; j < n_edge; ++j) edge_tip_(j) = bend[j](L).u;
  for (int j = 0; j < n_flap; ++j) flap_tip_(f0 + j) = bend[j](L).u;
  for (int j = 0; j < n_torsion; ++j) torsion_tip_(t0 + j) = twist[j](L).u;
  mass_llt_.compute(mass_);
}

Eigen::VectorXd PrebentSpinningBeam::acceleration(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot, double rate,
                                                  double angular_acceleration) const {
  const double r2 = rate * rate;
  return mass_llt_.solve(-angular_acceleration * euler_load_ + r2 * prebend_load_ - rate * gyroscopic_ * qdot -
                         (stiffness_ + r2 * (centrifugal_ - softening_) + angular_acceleration * alpha_coupling_) * q);
}

PrebentTipHistory prebent_spin_up_history(const PrebentSpinningBeam& beam, const HubSpin& hub, double end_s,
                                          double sample_s, double max_step_s) {
  if (!(end_s >= 0.0) || !(sample_s > 0.0) || !(max_step_s > 0.0))
    throw InputError({"flexbody", std::nullopt, "pre-bent spin-up run", "end ≥ 0, sample > 0, step > 0"},
                     "bad spin-up time settings");
  const auto samples = sampled_response(
      beam.size(),
      [&](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) {
        return Eigen::VectorXd(beam.acceleration(q, qdot, hub.rate(t), hub.acceleration(t)));
      },
      [&](const Eigen::VectorXd& q) { return Eigen::Vector3d(beam.edge_tip(q), beam.flap_tip(q), beam.torsion_tip(q)); },
      end_s, sample_s, max_step_s);
  PrebentTipHistory out;
  for (const Eigen::Vector3d& s : samples) {
    out.edge.push_back(s.x());
    out.flap.push_back(s.y());
    out.torsion.push_back(s.z());
  }
  return out;
}

}  // namespace fowtsim::flexbody
