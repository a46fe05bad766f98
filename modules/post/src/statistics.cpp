#include "fowtsim/post/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::post {

RowRange rows_in_window(std::span<const double> time_s, const std::optional<TimeWindow>& window) {
  RowRange rows{0, time_s.size()};
  if (window) {
    constexpr double slack_s = 1e-9;  // printed times (200.0 written as 2.000000E+02) match exactly
    rows.first = std::lower_bound(time_s.begin(), time_s.end(), window->start_s - slack_s) - time_s.begin();
    rows.last = std::upper_bound(time_s.begin(), time_s.end(), window->end_s + slack_s) - time_s.begin();
    rows.last = std::max(rows.last, rows.first);
  }
  if (rows.size() < 2) {
    const std::string span = time_s.empty() ? std::string("no samples")
                                            : fmt::format("samples from {} to {} s", time_s.front(), time_s.back());
    throw InputError({"post", std::nullopt, "window", "choose a window inside the record"},
                     window ? fmt::format("window {}–{} s holds fewer than two samples ({})", window->start_s,
                                          window->end_s, span)
                            : fmt::format("a record needs at least two samples ({})", span));
  }
  return rows;
}

ChannelStatistics channel_statistics(std::span<const double> time_s, std::span<const double> values) {
  if (values.empty() || time_s.size() != values.size())
    throw Error({"post", std::nullopt, "values", ""},
                fmt::format("channel_statistics: time_s.size() = {} and values.size() = {} must be equal and > 0",
                            time_s.size(), values.size()));
  ChannelStatistics s;
  s.samples = values.size();
  // A NaN poisons every statistic: reported as NaN, never as a plausible number (min/max comparisons
  // skip NaN, and a NaN variance would otherwise leave skewness and kurtosis at 0).
  if (std::any_of(values.begin(), values.end(), [](double v) { return std::isnan(v); })) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    s.min = s.max = s.mean = s.std = s.skewness = s.kurtosis = s.time_of_min_s = s.time_of_max_s = nan;
    return s;
  }
  const auto [min_it, max_it] = std::minmax_element(values.begin(), values.end());
  s.min = *min_it;
  s.max = *max_it;
  s.time_of_min_s = time_s[min_it - values.begin()];
  // minmax_element returns the last maximum; the table reports the first.
  s.time_of_max_s = time_s[std::find(values.begin(), values.end(), s.max) - values.begin()];

  const double n = static_cast<double>(values.size());
  double sum = 0.0;
  for (const double v : values) sum += v;
  s.mean = sum / n;
  double m2 = 0.0, m3 = 0.0, m4 = 0.0;
  for (const double v : values) {
    const double d = v - s.mean, d2 = d * d;
    m2 += d2;
    m3 += d2 * d;
    m4 += d2 * d2;
  }
  m2 /= n;
  m3 /= n;
  m4 /= n;
  s.std = std::sqrt(m2);
  if (m2 > 0.0) {
    s.skewness = m3 / (m2 * s.std);
    s.kurtosis = m4 / (m2 * m2);
  }
  return s;
}

}  // namespace fowtsim::post
