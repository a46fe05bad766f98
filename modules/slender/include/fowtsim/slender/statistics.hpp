#pragma once
// Statistics of sampled time-domain responses, to set them beside the frequency domain: the
// complex amplitude of one harmonic (a regular wave's steady state) and the standard deviation
// (an irregular sea's RMS about the mean).
#include "fowtsim/slender/wave_kinematics.hpp"  // VecXc

#include <complex>

namespace fowtsim::slender {

// Complex amplitude of the ω-component of a series sampled at interval dt over samples
// [first, first + count), count spanning whole periods: (2/count) Σ y_k e^{−iωt_k}, t_k = k dt.
std::complex<double> fourier_coefficient(const VecX& y, double omega_rad_s, double dt_s, Eigen::Index first,
                                         Eigen::Index count);

// Standard deviation of samples [first, first + count) (population form, 1/count).
double standard_deviation(const VecX& y, Eigen::Index first, Eigen::Index count);

// The same two statistics accumulated sample by sample over many series at once (one value per
// series per sample, e.g. per strip), for a time domain that keeps no history. Plain data: a part
// of a scene's state. No allocation once sized.

// Σ y_k e^{−iωt_k} per series: fourier_coefficient's sum, term by term in the same order.
struct HarmonicSums {
  VecXc sum;        // per series
  long count = 0;   // samples added
};
HarmonicSums make_harmonic_sums(Eigen::Index series);
void add_harmonic_sample(HarmonicSums& sums, const VecX& y, double omega_rad_s, double dt_s, long k);  // sample k: t_k = k dt
VecX harmonic_amplitudes(const HarmonicSums& sums);  // |2 Σ / count| per series

// Mean and Σ(y − mean)² per series by Welford's update (one pass, no cancellation).
struct DeviationSums {
  VecX mean;             // per series
  VecX squared_spread;   // Σ (y − mean)² per series
  long count = 0;
};
DeviationSums make_deviation_sums(Eigen::Index series);
void add_deviation_sample(DeviationSums& sums, const VecX& y);
VecX standard_deviations(const DeviationSums& sums);  // √(Σ(y − mean)²/count) per series

template <class Archive>
void fields(Archive& a, HarmonicSums& s) {
  a.io(s.sum, s.count);
}
template <class Archive>
void fields(Archive& a, DeviationSums& s) {
  a.io(s.mean, s.squared_spread, s.count);
}

}  // namespace fowtsim::slender
