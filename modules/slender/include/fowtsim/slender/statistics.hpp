#pragma once
// Statistics of sampled time-domain responses, to set them beside the frequency domain: the
// complex amplitude of one harmonic (a regular wave's steady state) and the standard deviation
// (an irregular sea's RMS about the mean).
#include "fowtsim/core/types.hpp"

#include <complex>

namespace fowtsim::slender {

// Complex amplitude of the ω-component of a series sampled at interval dt over samples
// [first, first + count), count spanning whole periods: (2/count) Σ y_k e^{−iωt_k}, t_k = k dt.
std::complex<double> fourier_coefficient(const VecX& y, double omega_rad_s, double dt_s, Eigen::Index first,
                                         Eigen::Index count);

// Standard deviation of samples [first, first + count) (population form, 1/count).
double standard_deviation(const VecX& y, Eigen::Index first, Eigen::Index count);

}  // namespace fowtsim::slender
