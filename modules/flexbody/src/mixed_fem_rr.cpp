#include "fowtsim/flexbody/mixed_fem_rr.hpp"

#include "fowtsim/core/error.hpp"

namespace fowtsim::flexbody {

MixedModel couple_rr_body(const Eigen::MatrixXd& Ma, const Eigen::MatrixXd& Ka,
                          const SampledBody& b) {
  const auto na = static_cast<int>(Ma.rows());
  const auto ng = static_cast<int>(b.u.cols());
  if (na < 2 || Ma.cols() != na || Ka.rows() != na || Ka.cols() != na)
    throw InputError({"flexbody", std::nullopt, "body a", "give square M^a, K^a ending in u_z, θ_y"},
                     "mixed FEM-RR coupling needs body a's matrices with B's two DOF last");
  double m0 = 0.0, m1 = 0.0, m2 = 0.0;  // ∫m, ∫m x, ∫m x² over body b
  for (const auto& p : b.points) {
    m0 += p.w * p.m;
    m1 += p.w * p.m * p.x;
    m2 += p.w * p.m * p.x * p.x;
  }
  Eigen::Matrix2d Mrr;
  Mrr << m0, -m1, -m1, m2;
  Eigen::MatrixXd Mrg(2, ng);
  Mrg.row(0) = mass_first_moment(b).transpose();
  Mrg.row(1) = -mass_axial_moment(b).transpose();
  const Eigen::Matrix2d Bp = Eigen::Vector2d(1.0, -1.0).asDiagonal();  // eq. 34 at θ_y = 0

  MixedModel out;
  const int n = na + ng;
  out.M = Eigen::MatrixXd::Zero(n, n);
  out.K = Eigen::MatrixXd::Zero(n, n);
  out.M.topLeftCorner(na, na) = Ma;
  out.M.block<2, 2>(na - 2, na - 2) += Bp.transpose() * Mrr * Bp;
  out.M.block(na - 2, na, 2, ng) = Bp.transpose() * Mrg;
  out.M.block(na, na - 2, ng, 2) = (Bp.transpose() * Mrg).transpose();
  out.M.bottomRightCorner(ng, ng) = generalized_mass(b);
  out.K.topLeftCorner(na, na) = Ka;
  out.K.bottomRightCorner(ng, ng) = generalized_stiffness(b);
  return out;
}

}  // namespace fowtsim::flexbody
