#include "fowtsim/flexbody/axial_force.hpp"

#include <algorithm>
#include <iterator>
#include <vector>

namespace fowtsim::flexbody {
namespace {

// ∫_x^L m(s) (a + b s) ds for m linear between stations. m (a + b s) is quadratic on an interval,
// so Simpson's rule on [x, x_{i+1}] and on each whole interval beyond is exact; the tail from each
// station to L is accumulated once.
AxialForce tip_integral(const BeamStations& s, double a, double b) {
  const std::size_t n = s.x.size();
  const auto f = [a, b](double m, double x) { return m * (a + b * x); };
  // f by value: the returned function outlives this frame (a [&] capture dangled).
  const auto simpson = [f](double x0, double m0, double x1, double m1) {
    return (x1 - x0) / 6.0 * (f(m0, x0) + 4.0 * f(0.5 * (m0 + m1), 0.5 * (x0 + x1)) + f(m1, x1));
  };
  std::vector<double> tail(n, 0.0);  // ∫_{x_i}^L
  for (std::size_t i = n - 1; i-- > 0;)
    tail[i] = tail[i + 1] + simpson(s.x[i], s.m[i], s.x[i + 1], s.m[i + 1]);
  return [s, tail, simpson](double x) {
    if (x >= s.x.back()) return 0.0;
    const auto it = std::upper_bound(s.x.begin(), s.x.end(), std::max(x, 0.0));
    const std::size_t i = static_cast<std::size_t>(std::distance(s.x.begin(), it)) - 1;
    const double fr = (x - s.x[i]) / (s.x[i + 1] - s.x[i]);
    const double mx = s.m[i] + fr * (s.m[i + 1] - s.m[i]);
    return tail[i + 1] + simpson(x, mx, s.x[i + 1], s.m[i + 1]);
  };
}

}  // namespace

AxialForce top_mass_axial_force(double top_mass, double gravity) {
  return [t = -top_mass * gravity](double) { return t; };
}

AxialForce self_weight_axial_force(const BeamStations& stations, double gravity) {
  return [mass = tip_integral(stations, 1.0, 0.0), gravity](double x) { return -gravity * mass(x); };
}

AxialForce centrifugal_axial_force(const BeamStations& stations, double omega, double root_radius) {
  return [moment = tip_integral(stations, root_radius, 1.0), w2 = omega * omega](double x) {
    return w2 * moment(x);
  };
}

}  // namespace fowtsim::flexbody
