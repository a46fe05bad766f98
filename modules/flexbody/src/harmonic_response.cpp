#include "fowtsim/flexbody/harmonic_response.hpp"

#include "fowtsim/core/error.hpp"
#include "fowtsim/flexbody/sampled_response.hpp"

#include <algorithm>
#include <cmath>

namespace fowtsim::flexbody {

Eigen::MatrixXd modal_stiffness_damping(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, double zeta) {
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(K.rows(), K.cols());
  for (Eigen::Index j = 0; j < K.rows(); ++j) D(j, j) = 2.0 * zeta / std::sqrt(K(j, j) / M(j, j)) * K(j, j);
  return D;
}

std::vector<double> harmonic_response(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D,
                                      const Eigen::MatrixXd& K, const Eigen::VectorXd& f, double Omega,
                                      const Eigen::VectorXd& c, double end_s, double sample_s,
                                      double max_step_s) {
  const Eigen::Index n = M.rows();
  if (M.cols() != n || D.rows() != n || D.cols() != n || K.rows() != n || K.cols() != n || f.size() != n ||
      c.size() != n || !(end_s >= 0.0) || !(sample_s > 0.0) || !(max_step_s > 0.0))
    throw InputError({"flexbody", std::nullopt, "harmonic response", "square n×n M, D, K; n-vectors; times > 0"},
                     "bad harmonic-response inputs");
  const Eigen::LLT<Eigen::MatrixXd> llt(M);
  return sampled_response(
      n,
      [&](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
        return Eigen::VectorXd(llt.solve(f * std::sin(Omega * t) - D * qd - K * q));
      },
      [&](const Eigen::VectorXd& q) { return c.dot(q); }, end_s, sample_s, max_step_s);
}

SingleDofTransient::SingleDofTransient(double w, double z, double Om, double xst)
    : omega(w), zeta(z), forcing(Om), static_amplitude(xst) {
  const double r = Om / w;
  H0 = xst / std::sqrt((1 - r * r) * (1 - r * r) + (2 * z * r) * (2 * z * r));
  phi = std::atan2(2 * z * r, 1 - r * r);
  const double wd = w * std::sqrt(1 - z * z);
  const double s = H0 * std::sin(phi);                                 // A sin ψ
  const double c = H0 * (z * w * std::sin(phi) - Om * std::cos(phi)) / wd;  // A cos ψ
  A = std::hypot(s, c);
  psi = std::atan2(s, c);
}

double SingleDofTransient::operator()(double t) const {
  const double wd = omega * std::sqrt(1 - zeta * zeta);
  return A * std::exp(-zeta * omega * t) * std::sin(wd * t + psi) + H0 * std::sin(forcing * t - phi);
}

}  // namespace fowtsim::flexbody
