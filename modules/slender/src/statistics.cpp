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

}  // namespace fowtsim::slender
