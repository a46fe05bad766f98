#include "fowtsim/post/welch_psd.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::post {

double uniform_sample_rate_hz(std::span<const double> time_s) {
  if (time_s.size() < 2)
    throw InputError({"post.psd", std::nullopt, "Time", ""}, "a spectrum needs at least two samples");
  const double step_s = (time_s.back() - time_s.front()) / static_cast<double>(time_s.size() - 1);
  for (std::size_t i = 1; i < time_s.size(); ++i) {
    const double step_i = time_s[i] - time_s[i - 1];
    if (!(step_s > 0.0) || std::abs(step_i - step_s) > 1e-6 * step_s)
      throw InputError({"post.psd", std::nullopt, "Time", "resample the record to a constant step"},
                       fmt::format("time steps are not uniform: step {} s at t = {} s against the mean step {} s",
                                   step_i, time_s[i - 1], step_s));
  }
  return 1.0 / step_s;
}

std::size_t segment_samples_for(double segment_s, double sample_rate_hz, std::size_t samples) {
  const auto requested = static_cast<std::size_t>(std::llround(std::max(segment_s * sample_rate_hz, 8.0)));
  return std::min(requested, samples);
}

namespace {

std::size_t checked_segment_samples(std::size_t segment_samples) {
  if (segment_samples < 2)
    throw Error({"post.psd", std::nullopt, "segment_samples", ""}, fmt::format("WelchEstimator: segment_samples = {} must be ≥ 2", segment_samples));
  return segment_samples;
}

}  // namespace

WelchEstimator::WelchEstimator(std::size_t segment_samples)
    : length_(checked_segment_samples(segment_samples)), window_(segment_samples), fft_(segment_samples) {
  for (std::size_t j = 0; j < segment_samples; ++j) {
    window_[j] = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(segment_samples)));
    window_power_ += window_[j] * window_[j];
  }
}

PowerSpectrum WelchEstimator::estimate(std::span<const double> values, double sample_rate_hz) const {
  const std::size_t length = length_, bins = length / 2 + 1;
  if (values.size() < length || !(sample_rate_hz > 0.0))
    throw Error({"post.psd", std::nullopt, "values", ""},
                fmt::format("WelchEstimator::estimate: values.size() = {} must be ≥ segment_samples = {} and "
                            "sample_rate_hz = {} > 0",
                            values.size(), length, sample_rate_hz));
  PowerSpectrum spectrum;
  spectrum.segment_samples = length;
  spectrum.frequency_hz.resize(bins);
  spectrum.density.assign(bins, 0.0);
  for (std::size_t k = 0; k < bins; ++k) spectrum.frequency_hz[k] = static_cast<double>(k) * sample_rate_hz / static_cast<double>(length);

  const std::size_t hop = std::max<std::size_t>(length / 2, 1);  // 50 % overlap
  for (std::size_t start = 0; start + length <= values.size(); start += hop) {
    const std::span<const double> segment = values.subspan(start, length);
    double mean = 0.0;
    for (const double v : segment) mean += v;
    mean /= static_cast<double>(length);
    double* samples = fft_.samples();
    for (std::size_t j = 0; j < length; ++j) samples[j] = window_[j] * (segment[j] - mean);
    const std::complex<double>* transform = fft_.execute();
    for (std::size_t k = 0; k < bins; ++k)
      spectrum.density[k] += transform[k].real() * transform[k].real() + transform[k].imag() * transform[k].imag();
    ++spectrum.segments;
  }
  const double scale = 1.0 / (sample_rate_hz * window_power_ * static_cast<double>(spectrum.segments));
  for (std::size_t k = 0; k < bins; ++k) {
    // One-sided: the negative frequencies fold onto the positive ones, except DC and Nyquist.
    const bool unpaired = k == 0 || (length % 2 == 0 && k == length / 2);
    spectrum.density[k] *= unpaired ? scale : 2.0 * scale;
  }
  return spectrum;
}

std::vector<SpectralPeak> spectral_peaks(const PowerSpectrum& spectrum, std::size_t count, double min_frequency_hz) {
  std::vector<SpectralPeak> peaks;
  const std::vector<double>& p = spectrum.density;
  for (std::size_t k = 1; k + 1 < p.size(); ++k)
    if (p[k] > p[k - 1] && p[k] >= p[k + 1] && spectrum.frequency_hz[k] >= min_frequency_hz)
      peaks.push_back({spectrum.frequency_hz[k], p[k]});
  const std::size_t kept = std::min(count, peaks.size());
  std::partial_sort(peaks.begin(), peaks.begin() + static_cast<std::ptrdiff_t>(kept), peaks.end(),
                    [](const SpectralPeak& a, const SpectralPeak& b) { return a.density > b.density; });
  peaks.resize(kept);
  return peaks;
}

}  // namespace fowtsim::post
