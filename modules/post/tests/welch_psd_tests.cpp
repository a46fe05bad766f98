// Welch spectra: Parseval, a sine's peak, white noise's level.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/post/welch_psd.hpp"

using namespace fowtsim::post;

namespace {

double integral(const PowerSpectrum& s) {
  const double df = s.frequency_hz[1] - s.frequency_hz[0];
  double sum = 0.0;
  for (const double p : s.density) sum += p * df;
  return sum;
}

double variance(const std::vector<double>& v) {
  double mean = 0.0, m2 = 0.0;
  for (const double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  for (const double x : v) m2 += (x - mean) * (x - mean);
  return m2 / static_cast<double>(v.size());
}

std::vector<double> white_noise(std::size_t n, double sigma, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, sigma);
  std::vector<double> v(n);
  for (double& x : v) x = normal(rng);
  return v;
}

}  // namespace

TEST_CASE("Welch PSD of sines at bin frequencies integrates to their variance exactly", "[verification]") {
  // Parseval with a periodic Hann window: a sine at bin k₀ ≥ 2 of every segment keeps Σ (w x)² /Σ w²
  // = A²/2 exactly, so ∫P df = Σ A²/2 to round-off. Source: Welch (1967) scaling, see welch_psd.hpp.
  const double fs = 20.0;
  const std::size_t length = 512;
  std::vector<double> v(length * 16);
  for (std::size_t j = 0; j < v.size(); ++j)
    v[j] = 1.5 * std::sin(2.0 * std::numbers::pi * 8.0 * j / length) + 0.5 * std::cos(2.0 * std::numbers::pi * 40.0 * j / length) + 4.0;
  const WelchEstimator welch(length);
  const PowerSpectrum s = welch.estimate(v, fs);
  CHECK(s.segments == 31u);  // (16·512 − 512)/256 + 1 with 50 % overlap
  CHECK(integral(s) == Approx(1.5 * 1.5 / 2 + 0.5 * 0.5 / 2).epsilon(5e-15));  // FFT round-off (measured 5.3e-16)
}

TEST_CASE("Welch PSD of white noise is flat at σ²/(fs/2) and integrates to the variance", "[verification]") {
  // White noise of variance σ² has the one-sided density σ²/(fs/2). Sampling error: averaging K
  // = 2047 Hann periodograms at 50 % overlap leaves a relative scatter of √((1 + 2·0.167²)/K) = 2.3 %
  // per bin (Welch 1967, overlap correlation of the Hann window): the mean over bins 2 … L/2 − 1
  // within 0.5 % (measured 0.11 %), every one of them within 10 % (4.4 scatters; measured max 5.9 %).
  // Bin 1 reads 5/6 of the level: removing each segment's mean also removes the window's DC lobe,
  // which reaches bin 1 with |W₁|²/(L Σw²) = (L/4)²/(L · 3L/8) = 1/6 (scipy's detrend="constant"
  // does the same); within 10 % of 5/6 (measured 0.1 %).
  const double fs = 10.0, sigma = 2.0;
  const std::vector<double> v = white_noise(1u << 18, sigma, 20260401u);
  const WelchEstimator welch(256);
  const PowerSpectrum s = welch.estimate(v, fs);
  const double level = sigma * sigma / (fs / 2.0);
  double mean_level = 0.0, worst = 0.0;
  for (std::size_t k = 2; k + 1 < s.density.size(); ++k) {
    mean_level += s.density[k];
    worst = std::max(worst, std::abs(s.density[k] / level - 1.0));
  }
  mean_level /= static_cast<double>(s.density.size() - 3);
  CHECK(mean_level == Approx(level).epsilon(0.005));
  CHECK(worst < 0.10);
  CHECK(s.density[1] == Approx(level * 5.0 / 6.0).epsilon(0.10));
  // Parseval: ∫P df equals the sample variance less what the mean removal takes out of white noise,
  // bin 0 whole and bins ±1 a sixth each of the two-sided 1/L per bin: a factor 1 − (4/3)/L (0.52 %
  // at L = 256). Within 0.5 %, the sampling error of the mean level (measured +0.11 %; −0.41 % without
  // the factor).
  CHECK(integral(s) == Approx(variance(v) * (1.0 - 4.0 / 3.0 / 256.0)).epsilon(0.005));
}

TEST_CASE("the highest PSD peak of a sine is at its frequency", "[verification]") {
  // A sine at 0.3 Hz in weaker noise; Δf = fs/L = 0.0390625 Hz. The peak bin is the one nearest
  // 0.3 Hz (within Δf/2), and the second sine at 1.04 Hz is the second peak.
  const double fs = 20.0;
  std::vector<double> v = white_noise(12000, 0.1, 7u);
  for (std::size_t j = 0; j < v.size(); ++j)
    v[j] += std::sin(2.0 * std::numbers::pi * 0.3 * j / fs) + 0.3 * std::sin(2.0 * std::numbers::pi * 1.04 * j / fs);
  const WelchEstimator welch(segment_samples_for(25.6, fs, v.size()));
  const PowerSpectrum s = welch.estimate(v, fs);
  const double df = fs / 512.0;
  const std::vector<SpectralPeak> peaks = spectral_peaks(s, 2);
  REQUIRE(peaks.size() == 2u);
  CHECK(std::abs(peaks[0].frequency_hz - 0.3) <= df / 2);
  CHECK(std::abs(peaks[1].frequency_hz - 1.04) <= df / 2);
  CHECK(spectral_peaks(s, 1, 0.5)[0].frequency_hz == peaks[1].frequency_hz);  // min_frequency_hz skips 0.3 Hz
}

TEST_CASE("sample rate and segment length come from the time column", "[unit]") {
  const std::vector<double> t{0.0, 0.05, 0.1, 0.15};
  CHECK(uniform_sample_rate_hz(t) == Approx(20.0).epsilon(1e-12));
  CHECK_THROWS_AS(uniform_sample_rate_hz(std::vector<double>{0.0, 0.05, 0.2}), fowtsim::InputError);
  CHECK(segment_samples_for(25.6, 20.0, 12000) == 512u);
  CHECK(segment_samples_for(1000.0, 20.0, 12000) == 12000u);  // one segment for a short record
}
