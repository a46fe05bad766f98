#include "fowtsim/flexbody/reduction.hpp"

#include "fowtsim/core/error.hpp"

#include <Eigen/Eigenvalues>

namespace fowtsim::flexbody {

ReducedBody craig_bampton(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, int masters, int k) {
  const auto n = static_cast<int>(K.rows());
  const int s = n - masters;
  if (!(masters > 0 && s > 0 && k >= 0 && k <= s) || M.rows() != n)
    throw InputError({"flexbody", std::nullopt, "reduction", "0 < masters < n, 0 <= k <= slaves"},
                     "invalid Guyan/Craig-Bampton reduction sizes");
  ReducedBody out;
  out.T = Eigen::MatrixXd::Zero(n, k + masters);
  out.T.bottomRightCorner(masters, masters).setIdentity();
  // Static constraint modes: the slaves' static response to unit master displacements.
  out.T.block(0, k, s, masters) = -K.topLeftCorner(s, s).ldlt().solve(K.topRightCorner(s, masters));
  if (k > 0) {
    // Fixed-interface modes: the slave block with the masters clamped; eigenvectors come
    // M_ss-normalised and in ascending frequency.
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> fixed(K.topLeftCorner(s, s),
                                                                          M.topLeftCorner(s, s));
    out.T.topLeftCorner(s, k) = fixed.eigenvectors().leftCols(k);
  }
  out.M = out.T.transpose() * M * out.T;
  out.K = out.T.transpose() * K * out.T;
  return out;
}

}  // namespace fowtsim::flexbody
