#pragma once
// One-sided power spectral density by Welch's method (P. D. Welch, "The use of fast Fourier
// transform for the estimation of power spectra", IEEE Trans. Audio Electroacoust. 15(2), 1967):
// segments of L samples overlapping by 50 %, each with its mean removed and a periodic Hann window
// w_j = ½(1 − cos 2πj/L), periodograms averaged. Units channel²/Hz, scaled so that the integral
// Σ P_k Δf equals the variance of the series (Parseval; up to the window's leakage):
//
//   P_k = c_k |Σ_j w_j x_j e^{−2πi jk/L}|² / (f_s Σ_j w_j²),  c_k = 2 except at k = 0 and k = L/2,
//
// the same estimate as scipy.signal.welch(x, fs, window="hann", nperseg=L, detrend="constant").
#include <cstddef>
#include <span>
#include <vector>

#include "fowtsim/core/fft.hpp"

namespace fowtsim::post {

struct PowerSpectrum {
  std::vector<double> frequency_hz;  // k f_s / L, k = 0 … L/2 [Hz]
  std::vector<double> density;       // P_k, channel²/Hz (one-sided)
  std::size_t segment_samples = 0;   // L
  std::size_t segments = 0;          // periodograms averaged
};

struct SpectralPeak {
  double frequency_hz = 0.0;  // frequency of the local maximum [Hz]
  double density = 0.0;       // PSD there, channel²/Hz
};

// Sample rate of a uniformly sampled time column [Hz]. Throws InputError when it holds fewer than
// two samples or a step differs from the mean step by more than 1e-6 of it (Welch needs uniform
// sampling; OpenFAST and our outputs write uniform steps).
double uniform_sample_rate_hz(std::span<const double> time_s);

// Segment length in samples for a requested segment duration: round(segment_s · f_s), at least 8
// and at most `samples` (a record shorter than one segment is one segment).
std::size_t segment_samples_for(double segment_s, double sample_rate_hz, std::size_t samples);

// Welch estimator for one segment length: the window and the FFT buffers are made once and reused
// for every channel of that length. Not copyable; estimate() is not thread-safe (it uses the buffers).
class WelchEstimator {
 public:
  explicit WelchEstimator(std::size_t segment_samples);  // L ≥ 2

  std::size_t segment_samples() const { return length_; }
  // PSD of `values` (at least L samples) sampled at sample_rate_hz.
  PowerSpectrum estimate(std::span<const double> values, double sample_rate_hz) const;

 private:
  std::size_t length_;         // L
  std::vector<double> window_;  // periodic Hann, L values
  double window_power_ = 0.0;   // Σ w_j²
  mutable ForwardRealFft fft_;  // the segment's transform, buffers reused by every estimate()
};

// The `count` highest local maxima of the spectrum (P_k > P_{k−1} and P_k ≥ P_{k+1}), highest
// first, at frequencies ≥ min_frequency_hz; the zero-frequency bin is never a peak.
std::vector<SpectralPeak> spectral_peaks(const PowerSpectrum& spectrum, std::size_t count, double min_frequency_hz = 0.0);

}  // namespace fowtsim::post
