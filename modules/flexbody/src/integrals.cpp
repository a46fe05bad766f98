#include "fowtsim/flexbody/integrals.hpp"

namespace fowtsim::flexbody {
namespace {

// ∫ f(x) a_i(x) b_j(x) dx as Aᵀ diag(w f) B.
Eigen::MatrixXd weighted_gram(const Eigen::MatrixXd& a, const Eigen::VectorXd& wf,
                              const Eigen::MatrixXd& b) {
  return a.transpose() * wf.asDiagonal() * b;
}

Eigen::VectorXd column(const SampledBody& body, double (*f)(const QuadraturePoint&)) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(body.points.size()));
  for (Eigen::Index k = 0; k < out.size(); ++k) out(k) = f(body.points[static_cast<std::size_t>(k)]);
  return out;
}

}  // namespace

SampledBody sample(const std::vector<QuadraturePoint>& points,
                   const std::vector<ShapeFunction>& shapes) {
  const auto np = static_cast<Eigen::Index>(points.size());
  const auto ns = static_cast<Eigen::Index>(shapes.size());
  SampledBody body{points, Eigen::MatrixXd(np, ns), Eigen::MatrixXd(np, ns), Eigen::MatrixXd(np, ns)};
  for (Eigen::Index k = 0; k < np; ++k)
    for (Eigen::Index j = 0; j < ns; ++j) {
      const ShapeValue v = shapes[static_cast<std::size_t>(j)](points[static_cast<std::size_t>(k)].x);
      body.u(k, j) = v.u;
      body.nu(k, j) = v.nu;
      body.kappa(k, j) = v.kappa;
    }
  return body;
}

Eigen::MatrixXd generalized_mass(const SampledBody& body) {
  return weighted_gram(body.u, column(body, [](const QuadraturePoint& p) { return p.w * p.m; }), body.u);
}

Eigen::MatrixXd generalized_stiffness(const SampledBody& body) {
  return weighted_gram(body.kappa, column(body, [](const QuadraturePoint& p) { return p.w * p.EI; }),
                       body.kappa);
}

Eigen::VectorXd mass_first_moment(const SampledBody& body) {
  return body.u.transpose() * column(body, [](const QuadraturePoint& p) { return p.w * p.m; });
}

Eigen::VectorXd mass_axial_moment(const SampledBody& body) {
  return body.u.transpose() * column(body, [](const QuadraturePoint& p) { return p.w * p.m * p.x; });
}

Eigen::MatrixXd geometric_stiffness(const SampledBody& body, const AxialForce& axial_force) {
  Eigen::VectorXd wT(static_cast<Eigen::Index>(body.points.size()));
  for (Eigen::Index k = 0; k < wT.size(); ++k) {
    const QuadraturePoint& p = body.points[static_cast<std::size_t>(k)];
    wT(k) = p.w * axial_force(p.x);  // eq. 26: K^T_ij = ∫ T ν_i ν_j dx
  }
  return weighted_gram(body.nu, wT, body.nu);
}

}  // namespace fowtsim::flexbody
