#include "fowtsim/flexbody/station_segment.hpp"

#include "fowtsim/core/error.hpp"

#include <algorithm>
#include <iterator>

namespace fowtsim::flexbody {
namespace {

// m and EI at x, linear between the stations around it.
std::pair<double, double> at(const BeamStations& s, double x) {
  const auto hi = std::upper_bound(s.x.begin() + 1, s.x.end() - 1, x);
  const auto i = static_cast<std::size_t>(std::distance(s.x.begin(), hi)) - 1;
  const double f = (x - s.x[i]) / (s.x[i + 1] - s.x[i]);
  return {s.m[i] + f * (s.m[i + 1] - s.m[i]), s.EI[i] + f * (s.EI[i + 1] - s.EI[i])};
}

}  // namespace

BeamStations segment(const BeamStations& s, double a, double b) {
  if (s.x.size() < 2 || !(a >= 0.0 && a < b && b <= s.length()))
    throw InputError({"flexbody", std::nullopt, "segment", "give 0 <= a < b <= L"},
                     "segment outside the station table");
  BeamStations out;
  const auto push = [&out, a](double x, double m, double EI) {
    out.x.push_back(x - a);
    out.m.push_back(m);
    out.EI.push_back(EI);
  };
  const auto [ma, EIa] = at(s, a);
  push(a, ma, EIa);
  for (std::size_t i = 0; i < s.x.size(); ++i)
    if (s.x[i] > a && s.x[i] < b) push(s.x[i], s.m[i], s.EI[i]);
  const auto [mb, EIb] = at(s, b);
  push(b, mb, EIb);
  return out;
}

}  // namespace fowtsim::flexbody
