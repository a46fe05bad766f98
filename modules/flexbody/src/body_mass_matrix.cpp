#include "fowtsim/flexbody/body_mass_matrix.hpp"

#include "fowtsim/core/error.hpp"

namespace fowtsim::flexbody {
namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

}  // namespace

Eigen::MatrixXd body_mass_matrix(const ShapeIntegrals& si, const Eigen::VectorXd& g) {
  const int nf = si.shapes();
  if (g.size() != nf)
    throw InputError({"flexbody", std::nullopt, "deflection g", "give one value per shape"},
                     "body mass matrix: g has the wrong size");
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(6 + nf, 6 + nf);
  M.topLeftCorner<3, 3>() = si.mass * Eigen::Matrix3d::Identity();
  const Eigen::Vector3d first = si.sigma + si.Psi * g;  // ∫ s dm
  M.block<3, 3>(0, 3) = -skew(first);
  M.block(0, 6, 3, nf) = si.Psi;
  // u_kl = ∫ s_k s_l dm (eq. 38).
  Eigen::Matrix3d u;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l)
      u(k, l) = si.sigma2(k, l) + (si.Sigma[k][l] + si.Sigma[l][k]).dot(g) + g.dot(si.Upsilon[k][l] * g);
  // −∫ s̃ s̃ dm = tr(u) I − u.
  M.block<3, 3>(3, 3) = u.trace() * Eigen::Matrix3d::Identity() - u;
  // ∫ s̃ Φ dm, row k = ∫ (s_a Φ_b − s_b Φ_a) for (k, a, b) cyclic.
  for (int k = 0; k < 3; ++k) {
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    M.block(3 + k, 6, 1, nf) =
        g.transpose() * (si.Upsilon[a][b] - si.Upsilon[b][a]) + si.Sigma[a][b] - si.Sigma[b][a];
  }
  M.bottomRightCorner(nf, nf) = si.Upsilon[0][0] + si.Upsilon[1][1] + si.Upsilon[2][2];
  M.triangularView<Eigen::StrictlyLower>() = M.transpose();
  return M;
}

Eigen::Matrix<double, 6, 6> rigid_body_mass_matrix(double mass, const Eigen::Vector3d& cog,
                                                  const Eigen::Matrix3d& inertia_at_origin) {
  Eigen::Matrix<double, 6, 6> M;
  M << mass * Eigen::Matrix3d::Identity(), -mass * skew(cog), mass * skew(cog), inertia_at_origin;
  return M;
}

void add_section_inertia(Eigen::MatrixXd& M, double polar_inertia, const Eigen::VectorXd& torsion_coupling,
                         const Eigen::MatrixXd& torsion_mass) {
  const Eigen::Index nf = M.rows() - 6;
  if ((torsion_coupling.size() != 0 && torsion_coupling.size() != nf) ||
      (torsion_mass.size() != 0 && (torsion_mass.rows() != nf || torsion_mass.cols() != nf)))
    throw InputError({"flexbody", std::nullopt, "torsion terms", "give one value per shape"},
                     "section inertia: torsion terms do not match the body's shapes");
  M(3, 3) += polar_inertia;
  if (torsion_coupling.size() != 0) {
    M.block(3, 6, 1, nf) += torsion_coupling.transpose();
    M.block(6, 3, nf, 1) += torsion_coupling;
  }
  if (torsion_mass.size() != 0) M.bottomRightCorner(nf, nf) += torsion_mass;
}

void apply_axial_inertia_correction(Eigen::MatrixXd& M, const SampledBody& body, const Eigen::VectorXd& g,
                                    const AxialForce& unit_axial_load) {
  const Eigen::Index nf = body.nu.cols();
  if (g.size() != nf || M.rows() != 6 + nf)
    throw InputError({"flexbody", std::nullopt, "deflection g", "give one value per shape"},
                     "axial-inertia correction: sizes of g, M and the body disagree");
  Eigen::VectorXd wT(static_cast<Eigen::Index>(body.points.size()));
  for (Eigen::Index k = 0; k < wT.size(); ++k) {
    const QuadraturePoint& p = body.points[static_cast<std::size_t>(k)];
    wT(k) = p.w * unit_axial_load(p.x);
  }
  const Eigen::VectorXd nu = body.nu * g;  // ν_z of the deflected beam at the points
  M(0, 4) = M(4, 0) = wT.dot(nu);          // eq. 28, M_15
  M(0, 5) = M(5, 0) = 0.0;                 // eq. 28, M_16: no y deflection
  const Eigen::VectorXd row = -(body.nu.transpose() * wT.cwiseProduct(nu));  // eq. 29
  M.block(0, 6, 1, nf) = row.transpose();
  M.block(6, 0, nf, 1) = row;
}

}  // namespace fowtsim::flexbody
