#include "compare/window_statistics.hpp"

#include <cmath>
#include <string>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/interpolation.hpp"

namespace fowtsim::driver {
namespace {

const std::vector<double>& channel(const io::ChannelTable& t, std::string_view name) {
  const auto i = t.find(name);
  if (!i) throw InputError({"compare", std::nullopt, std::string(name), "a channel of the run"}, "channel " + std::string(name) + " not found");
  return t.columns[*i];
}

}  // namespace

PairedSeries paired_series(const io::ChannelTable& ref, std::string_view ref_name, const io::ChannelTable& test,
                           std::string_view test_name, double t0, double t1, double test_scale) {
  const auto& tr = ref.time();
  const auto& r = channel(ref, ref_name);
  const auto& o = channel(test, test_name);
  PairedSeries p;
  for (std::size_t i = 0; i < tr.size(); ++i)
    if (tr[i] >= t0 && tr[i] <= t1) {
      p.ref.push_back(r[i]);
      p.test.push_back(test_scale * interpolate_linear(test.time(), o, tr[i]));
    }
  return p;
}

double mean(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

double standard_deviation(const std::vector<double>& v) {
  const double m = mean(v);
  double s = 0.0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / static_cast<double>(v.size()));
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double ma = mean(a), mb = mean(b);
  double ab = 0.0, aa = 0.0, bb = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ab += (a[i] - ma) * (b[i] - mb);
    aa += (a[i] - ma) * (a[i] - ma);
    bb += (b[i] - mb) * (b[i] - mb);
  }
  return aa > 0.0 && bb > 0.0 ? ab / std::sqrt(aa * bb) : std::nan("");
}

}  // namespace fowtsim::driver
