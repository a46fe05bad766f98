#include "fowtsim/hydro/kernel_realization.hpp"

#include <cmath>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::hydro {
namespace {

// Poles of the order-n realisation: the shifted Hankel matrix H1 projected on the leading n
// singular directions of H0 is the discrete system matrix (Kung 1978, eq. 24); its eigenvalues μ
// give p = ln μ / Δt. Unstable (|μ| ≥ 1) and negative real μ (a Nyquist oscillation) are dropped;
// of a conjugate pair the member with Im p > 0 is kept.
std::vector<ExponentialTerm> realised_poles(const Eigen::BDCSVD<Eigen::MatrixXd>& svd, const Eigen::MatrixXd& h1, int order,
                                            double dt) {
  const Eigen::MatrixXd u = svd.matrixU().leftCols(order);
  const Eigen::MatrixXd v = svd.matrixV().leftCols(order);
  const Eigen::VectorXd inv_sqrt = svd.singularValues().head(order).cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd a = inv_sqrt.asDiagonal() * (u.transpose() * h1 * v) * inv_sqrt.asDiagonal();
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(a, false);
  std::vector<ExponentialTerm> terms;
  for (const std::complex<double>& mu : eigen.eigenvalues()) {
    if (!(std::abs(mu) < 1.0) || std::abs(mu) == 0.0) continue;
    const bool real = std::abs(mu.imag()) <= 1e-12 * std::abs(mu);
    if (real && mu.real() < 0.0) continue;
    if (!real && mu.imag() < 0.0) continue;
    terms.push_back({std::log(real ? std::complex<double>(mu.real(), 0.0) : mu) / dt, 0.0, real ? 1.0 : 2.0});
  }
  return terms;
}

// Residues by least squares over the samples: a real pole has one real unknown, a pair two
// (w Re(r e^{pt}) = 2 Re r Re e^{pt} − 2 Im r Im e^{pt}). Returns the relative error.
double fit_residues(std::span<const double> samples, double dt, std::vector<ExponentialTerm>& terms) {
  const auto n = static_cast<Eigen::Index>(samples.size());
  Eigen::Index unknowns = 0;
  for (const ExponentialTerm& t : terms) unknowns += t.weight == 2.0 ? 2 : 1;
  const Eigen::Map<const Eigen::VectorXd> y(samples.data(), n);
  if (unknowns == 0) return 1.0;
  Eigen::MatrixXd basis(n, unknowns);
  Eigen::Index c = 0;
  for (const ExponentialTerm& t : terms) {
    for (Eigen::Index k = 0; k < n; ++k) {
      const std::complex<double> e = std::exp(t.pole * (static_cast<double>(k) * dt));
      basis(k, c) = t.weight * e.real();
      if (t.weight == 2.0) basis(k, c + 1) = -t.weight * e.imag();
    }
    c += t.weight == 2.0 ? 2 : 1;
  }
  const Eigen::VectorXd x = basis.colPivHouseholderQr().solve(y);
  c = 0;
  for (ExponentialTerm& t : terms) {
    t.residue = t.weight == 2.0 ? std::complex<double>(x[c], x[c + 1]) : std::complex<double>(x[c], 0.0);
    c += t.weight == 2.0 ? 2 : 1;
  }
  return (basis * x - y).norm() / y.norm();
}

}  // namespace

ExponentialFit fit_exponentials(std::span<const double> samples, double dt_s, double tolerance, int max_order) {
  if (samples.size() < 8 || !(dt_s > 0.0) || max_order < 2)
    throw InputError({"hydro.state_space", std::nullopt, "kernel samples", "≥ 8 samples, Δt > 0, max_order ≥ 2"},
                     fmt::format("cannot fit {} samples at Δt = {} s up to order {}", samples.size(), dt_s, max_order));
  for (double s : samples)
    if (!std::isfinite(s))
      throw NumericalError({"hydro.state_space", std::nullopt, "kernel samples", "check the radiation damping table"},
                           "non-finite kernel sample");
  double norm = 0.0;
  for (double s : samples) norm += s * s;
  if (norm == 0.0) return {};
  const auto n = static_cast<Eigen::Index>(samples.size());
  const Eigen::Index rows = (n - 1) / 2, cols = n - 1 - rows;
  Eigen::MatrixXd h0(rows, cols), h1(rows, cols);
  for (Eigen::Index i = 0; i < rows; ++i)
    for (Eigen::Index j = 0; j < cols; ++j) {
      h0(i, j) = samples[static_cast<std::size_t>(i + j)];
      h1(i, j) = samples[static_cast<std::size_t>(i + j + 1)];
    }
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(h0, Eigen::ComputeThinU | Eigen::ComputeThinV);
  ExponentialFit best;
  best.relative_error = 2.0;
  for (int order = 1; order <= max_order && order <= static_cast<int>(std::min(rows, cols)); ++order) {
    if (svd.singularValues()[order - 1] <= 1e-14 * svd.singularValues()[0]) break;  // no more information
    ExponentialFit fit;
    fit.order = order;
    fit.terms = realised_poles(svd, h1, order, dt_s);
    fit.relative_error = fit_residues(samples, dt_s, fit.terms);
    if (fit.relative_error < best.relative_error) best = fit;
    if (best.relative_error < tolerance) break;
  }
  return best;
}

double evaluate(const ExponentialFit& fit, double t_s) {
  double k = 0.0;
  for (const ExponentialTerm& term : fit.terms) k += term.weight * (term.residue * std::exp(term.pole * t_s)).real();
  return k;
}

}  // namespace fowtsim::hydro
