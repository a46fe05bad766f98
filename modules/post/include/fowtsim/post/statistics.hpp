#pragma once
// Summary statistics of one channel over a time window, the numbers MLife and pCrunch tabulate.
// Moments are population moments (divide by n, as numpy's default and pCrunch): std = √m₂,
// skewness = m₃ / m₂^{3/2}, kurtosis = m₄ / m₂² — the plain kurtosis, 3 for a Gaussian, 1.5 for a
// sine (not the excess kurtosis, which subtracts 3). m_k = (1/n) Σ (x − mean)^k.
#include <cstddef>
#include <optional>
#include <span>

namespace fowtsim::post {

struct TimeWindow {
  double start_s = 0.0;  // first time kept [s] (inclusive)
  double end_s = 0.0;    // last time kept [s] (inclusive)
};

// Rows [first, last) of a time column that lie inside a window.
struct RowRange {
  std::size_t first = 0;  // first row inside
  std::size_t last = 0;   // one past the last row inside
  std::size_t size() const { return last - first; }
};

// The rows of `time_s` (non-decreasing) with start_s ≤ t ≤ end_s, with 1e-9 s of slack so that
// printed times such as 200.0 match; the whole column without a window. Throws InputError when
// fewer than two rows remain.
RowRange rows_in_window(std::span<const double> time_s, const std::optional<TimeWindow>& window);

struct ChannelStatistics {
  double min = 0.0;            // smallest value, channel unit
  double max = 0.0;            // largest value, channel unit
  double mean = 0.0;           // arithmetic mean, channel unit
  double std = 0.0;            // population standard deviation √m₂, channel unit
  double skewness = 0.0;       // m₃ / m₂^{3/2}, –; 0 for a constant channel
  double kurtosis = 0.0;       // m₄ / m₂² (not excess), –; 0 for a constant channel
  double time_of_min_s = 0.0;  // time of the first sample equal to min [s]
  double time_of_max_s = 0.0;  // time of the first sample equal to max [s]
  std::size_t samples = 0;     // number of samples used
};

// Statistics of `values` sampled at `time_s` (same length, at least one sample). Two passes (mean,
// then central moments) so a large mean does not swamp the variance of a small oscillation. A
// channel holding a NaN gets NaN for every statistic (samples still counted).
ChannelStatistics channel_statistics(std::span<const double> time_s, std::span<const double> values);

}  // namespace fowtsim::post
