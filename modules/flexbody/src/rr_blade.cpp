#include "fowtsim/flexbody/rr_blade.hpp"

#include "fowtsim/flexbody/axial_force.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>

namespace fowtsim::flexbody {
namespace {

// Σ_k w_k c_k a_k,i b_k,j over the points, for (point, shape) matrices a, b and weights w·c.
Eigen::Matrix3d weighted(const Eigen::VectorXd& wc, const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.transpose() * wc.asDiagonal() * b;
}

Eigen::VectorXd per_point(const SampledBlade& s, double (*f)(const BladePoint&)) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(s.points.size()));
  for (std::size_t k = 0; k < s.points.size(); ++k) v(static_cast<Eigen::Index>(k)) = s.points[k].w * f(s.points[k]);
  return v;
}

}  // namespace

BladeMassProperties mass_properties(const SampledBlade& s) {
  BladeMassProperties p;
  for (const BladePoint& q : s.points) {
    p.mass += q.w * q.m;
    p.first_moment += q.w * q.m * q.x;
    p.second_moment += q.w * q.m * q.x * q.x;
  }
  return p;
}

RrBladeMatrices rr_blade_matrices(const ElastoDynBlade& blade, const SampledBlade& s) {
  const Eigen::VectorXd wm = per_point(s, [](const BladePoint& p) { return p.m; });
  const Eigen::VectorXd wf = per_point(s, [](const BladePoint& p) { return p.EI_flap; });
  const Eigen::VectorXd we = per_point(s, [](const BladePoint& p) { return p.EI_edge; });
  const AxialForce tension = centrifugal_axial_force(blade_stations(blade), 1.0, blade.hub_radius);  // T/Ω²
  Eigen::VectorXd wt(wm.size());
  for (Eigen::Index k = 0; k < wt.size(); ++k) {
    const BladePoint& p = s.points[static_cast<std::size_t>(k)];
    wt(k) = p.w * tension(p.x);
  }
  RrBladeMatrices m;
  m.mass = weighted(wm, s.u_flap, s.u_flap) + weighted(wm, s.u_edge, s.u_edge);
  m.stiffness = weighted(wf, s.kappa_f, s.kappa_f) + weighted(we, s.kappa_e, s.kappa_e);
  const Eigen::Vector3d tuner(blade.flap_stiffness_tuners[0], blade.flap_stiffness_tuners[1], 1.0);
  m.stiffness = m.stiffness.cwiseProduct((tuner * tuner.transpose()).cwiseSqrt());
  m.centrifugal = weighted(wt, s.nu_flap, s.nu_flap) + weighted(wt, s.nu_edge, s.nu_edge);
  m.softening = weighted(wm, s.u_edge, s.u_edge);
  m.mass_polynomial = weighted(wm, s.phi, s.phi).diagonal();
  m.centrifugal_polynomial = weighted(wt, s.dphi, s.dphi).diagonal();
  return m;
}

Eigen::Vector3d natural_frequencies_hz(const RrBladeMatrices& m, double omega) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix3d> eig(m.stiffness_at(omega), m.mass,
                                                                       Eigen::EigenvaluesOnly);
  return eig.eigenvalues().cwiseSqrt() / (2.0 * std::numbers::pi);  // ascending
}

Eigen::Vector3d elastodyn_frequencies_hz(const RrBladeMatrices& m, double omega) {
  const Eigen::Vector3d k = m.stiffness.diagonal() + omega * omega * m.centrifugal_polynomial;
  return k.cwiseQuotient(m.mass_polynomial).cwiseSqrt() / (2.0 * std::numbers::pi);
}

Eigen::Matrix3d elastodyn_damping(const ElastoDynBlade& blade, const RrBladeMatrices& m) {
  const Eigen::Vector3d zeta(blade.flap_damping_percent[0], blade.flap_damping_percent[1], blade.edge_damping_percent);
  const Eigen::Vector3d f = elastodyn_frequencies_hz(m);
  const Eigen::Vector3d column = (0.01 * zeta).cwiseQuotient(std::numbers::pi * f);
  return m.stiffness * column.asDiagonal();
}

}  // namespace fowtsim::flexbody
