// Statistics of a channel against closed forms.
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/post/record_checks.hpp"
#include "fowtsim/post/statistics.hpp"

using namespace fowtsim::post;

namespace {

// A sin(2π j/64) at dt = 0.05 s over whole periods, without the repeated end point: the discrete
// moments are then exactly those of the continuous sine (Σ sin² = N/2, Σ sin⁴ = 3N/8 over whole
// periods of 64 samples).
struct SampledSine {
  std::vector<double> time_s, values;
};
SampledSine sampled_sine(double amplitude, double mean, int periods) {
  constexpr int per_period = 64;
  SampledSine s;
  for (int j = 0; j < periods * per_period; ++j) {
    s.time_s.push_back(0.05 * j);
    s.values.push_back(mean + amplitude * std::sin(2.0 * std::numbers::pi * (j % per_period) / per_period));
  }
  return s;
}

}  // namespace

TEST_CASE("statistics of a sine equal the closed forms", "[unit]") {
  // Intent: mean, population std, skewness and plain (not excess) kurtosis of a whole-period sine.
  const double amplitude = 2.5, mean = 7.0;
  const SampledSine s = sampled_sine(amplitude, mean, 10);
  const ChannelStatistics st = channel_statistics(s.time_s, s.values);
  // Exact in exact arithmetic; the tolerances cover the round-off of 640-term sums of numbers near 10,
  // 10× the measured residual: mean 1.8e-15, std 0, skewness 2.8e-15 absolute, kurtosis 2.5e-15.
  CHECK(st.mean == Approx(mean).margin(2e-14));
  CHECK(st.std == Approx(amplitude / std::sqrt(2.0)).epsilon(1e-14));  // A/√2
  CHECK(st.skewness == Approx(0.0).margin(3e-14));                      // odd moment of a symmetric wave
  CHECK(st.kurtosis == Approx(1.5).epsilon(3e-14));                     // m₄/m₂² = (3A⁴/8)/(A²/2)² = 1.5
  CHECK(st.max == mean + amplitude);  // sin(π/2) = 1 exactly at j = 16
  CHECK(st.min == mean - amplitude);
  CHECK(st.time_of_max_s == 0.05 * 16);  // first peak, not a later one
  CHECK(st.time_of_min_s == 0.05 * 48);
  CHECK(st.samples == 640u);
}

TEST_CASE("a Bernoulli series has the skewness and kurtosis of its closed form", "[unit]") {
  // Intent: the third and fourth moments are the population ones: for values 1 with probability p
  // and 0 otherwise, skewness (1 − 2p)/√(p(1 − p)) and kurtosis (1 − 3p(1 − p))/(p(1 − p)).
  std::vector<double> t, v;
  for (int i = 0; i < 100; ++i) {
    t.push_back(i);
    v.push_back(i % 4 == 0 ? 1.0 : 0.0);  // p = 1/4
  }
  const ChannelStatistics st = channel_statistics(t, v);
  const double p = 0.25, q = 0.75;
  // Round-off only (measured 1.9e-16 and 0): 2e-15.
  CHECK(st.skewness == Approx((1 - 2 * p) / std::sqrt(p * q)).epsilon(2e-15));
  CHECK(st.kurtosis == Approx((1 - 3 * p * q) / (p * q)).epsilon(2e-15));
  CHECK(st.time_of_max_s == 0.0);
}

TEST_CASE("a constant channel has zero std, skewness and kurtosis", "[unit]") {
  const std::vector<double> t{0, 1, 2}, v{4, 4, 4};
  const ChannelStatistics st = channel_statistics(t, v);
  CHECK(st.std == 0.0);
  CHECK(st.skewness == 0.0);
  CHECK(st.kurtosis == 0.0);
  CHECK(st.time_of_min_s == 0.0);
  CHECK(st.time_of_max_s == 0.0);
}

TEST_CASE("a window keeps the rows between its ends, inclusive", "[unit]") {
  const std::vector<double> t{0.0, 0.5, 1.0, 1.5, 2.0, 2.5};
  const RowRange all = rows_in_window(t, std::nullopt);
  CHECK((all.first == 0 && all.last == 6));
  const RowRange inner = rows_in_window(t, TimeWindow{0.5, 2.0});
  CHECK((inner.first == 1 && inner.last == 5));
  const RowRange slack = rows_in_window(t, TimeWindow{0.5 + 1e-12, 2.0 - 1e-12});  // printed times
  CHECK((slack.first == 1 && slack.last == 5));
  CHECK_THROWS_AS(rows_in_window(t, TimeWindow{3.0, 4.0}), fowtsim::InputError);
  CHECK_THROWS_AS(rows_in_window(t, TimeWindow{0.6, 0.9}), fowtsim::InputError);
}

TEST_CASE("a channel holding NaN has NaN statistics, not a plausible skewness of 0", "[unit][post]") {
  // Intent: min/max comparisons skip NaN and a NaN variance left skewness and kurtosis at 0.
  const std::vector<double> t{0.0, 0.1, 0.2, 0.3};
  const std::vector<double> v{1.0, 2.0, std::numeric_limits<double>::quiet_NaN(), 1.0};
  const ChannelStatistics s = channel_statistics(t, v);
  CHECK(s.samples == 4);
  for (double x : {s.min, s.max, s.mean, s.std, s.skewness, s.kurtosis, s.time_of_min_s, s.time_of_max_s}) CHECK(std::isnan(x));
}

TEST_CASE("a record whose time goes backwards, or a channel with NaN, is refused with its row and time", "[unit][post]") {
  const std::vector<double> t{0.0, 0.1, 0.05, 0.3};
  CHECK_THROWS_WITH(check_time_order(t, "run.out"),
                    Catch::Contains("run.out: time goes backwards at data row 3: 0.05 s after 0.1 s"));
  CHECK_NOTHROW(check_time_order(std::vector<double>{0.0, 0.1, 0.1, 0.2}, "run.out"));  // repeats are not disorder
  const std::vector<double> times{1.0, 1.1, 1.2}, values{1.0, std::numeric_limits<double>::quiet_NaN(), 2.0};
  // The window starts at data row 11: the NaN is row 12, at t = 1.1 s.
  CHECK_THROWS_WITH(check_no_nan(times, values, 10, "run.out", "TwrBsMyt"),
                    Catch::Contains("run.out: channel TwrBsMyt is NaN from data row 12 (t = 1.1 s)"));
  CHECK_NOTHROW(check_no_nan(times, std::vector<double>{1.0, 2.0, 3.0}, 0, "run.out", "TwrBsMyt"));
}
