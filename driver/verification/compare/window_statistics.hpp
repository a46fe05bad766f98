#pragma once
// Statistics of a channel against a reference run over a time window: the two series on the
// reference's samples (ours interpolated onto them), their means, standard deviations and
// correlation — how the flexible-turbine checks and `fowtsim compare` compare runs.
#include <string_view>
#include <vector>

#include "fowtsim/io/channel_table.hpp"

namespace fowtsim::driver {

struct PairedSeries {
  std::vector<double> ref, test;
};

// ref_name of `ref` and test_name of `test` (times `test_scale`, e.g. 1e3 for kN → N) at the
// reference's times in [t0, t1]. Throws InputError when a channel is missing.
PairedSeries paired_series(const io::ChannelTable& ref, std::string_view ref_name, const io::ChannelTable& test,
                           std::string_view test_name, double t0, double t1, double test_scale = 1.0);

double mean(const std::vector<double>& v);
double standard_deviation(const std::vector<double>& v);
// Pearson correlation; NaN when either series is constant.
double correlation(const std::vector<double>& a, const std::vector<double>& b);
inline double correlation(const PairedSeries& p) { return correlation(p.ref, p.test); }

}  // namespace fowtsim::driver
