#include "fowtsim/slender/statistics.hpp"

#include <cmath>

namespace fowtsim::slender {

std::complex<double> fourier_coefficient(const VecX& y, double omega, double dt, Eigen::Index first, Eigen::Index count) {
  std::complex<double> sum = 0.0;
  for (Eigen::Index k = first; k < first + count; ++k)
    sum += y(k) * std::exp(std::complex<double>(0.0, -omega * static_cast<double>(k) * dt));
  return 2.0 * sum / static_cast<double>(count);
}

double standard_deviation(const VecX& y, Eigen::Index first, Eigen::Index count) {
  const auto window = y.segment(first, count).array();
  return std::sqrt((window - window.mean()).square().mean());
}

HarmonicSums make_harmonic_sums(Eigen::Index series) { return {VecXc::Zero(series), 0}; }

void add_harmonic_sample(HarmonicSums& s, const VecX& y, double omega, double dt, long k) {
  const std::complex<double> phasor = std::exp(std::complex<double>(0.0, -omega * static_cast<double>(k) * dt));
  for (Eigen::Index i = 0; i < y.size(); ++i) s.sum(i) += y(i) * phasor;
  ++s.count;
}

VecX harmonic_amplitudes(const HarmonicSums& s) {
  return s.sum.unaryExpr([&](std::complex<double> sum) { return std::abs(2.0 * sum / static_cast<double>(s.count)); });
}

DeviationSums make_deviation_sums(Eigen::Index series) { return {VecX::Zero(series), VecX::Zero(series), 0}; }

void add_deviation_sample(DeviationSums& s, const VecX& y) {
  ++s.count;
  const double count = static_cast<double>(s.count);
  for (Eigen::Index i = 0; i < y.size(); ++i) {
    const double before = y(i) - s.mean(i);
    s.mean(i) += before / count;
    s.squared_spread(i) += before * (y(i) - s.mean(i));
  }
}

VecX standard_deviations(const DeviationSums& s) { return (s.squared_spread / static_cast<double>(s.count)).cwiseSqrt(); }

}  // namespace fowtsim::slender
