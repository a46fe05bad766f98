#pragma once
// A second-order system q̈ = a(t, q, q̇) integrated from rest (q = q̇ = 0 at t = 0) with the
// classical fourth-order Runge–Kutta step (core/rk4.hpp) on y = [q; q̇], sampled at a fixed
// interval: the time loop the seed's unsteady checks (Sec. 5.2 spin-up, Sec. 5.3 torsion) share.
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "fowtsim/core/rk4.hpp"

namespace fowtsim::flexbody {

// observe(q) at t = k·sample_s, k = 0 … round(end_s/sample_s), with ⌈sample_s/max_step_s⌉ equal
// steps per sample; `acceleration(t, q, q̇)` returns q̈ (n values). The caller checks the times.
template <class Acceleration, class Observe>
std::vector<std::invoke_result_t<const Observe&, Eigen::VectorXd>> sampled_response(Eigen::Index n, const Acceleration& acceleration, const Observe& observe,
                                     double end_s, double sample_s, double max_step_s) {
  const auto rate = [&](double t, const Eigen::VectorXd& y) {
    Eigen::VectorXd out(2 * n);
    out.head(n) = y.tail(n);
    out.tail(n) = acceleration(t, y.head(n), y.tail(n));
    return out;
  };
  const long samples = std::lround(end_s / sample_s);
  const long substeps = std::max(1L, static_cast<long>(std::ceil(sample_s / max_step_s - 1e-9)));
  const double dt = sample_s / static_cast<double>(substeps);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(2 * n);
  std::vector<std::invoke_result_t<const Observe&, Eigen::VectorXd>> out{observe(Eigen::VectorXd(y.head(n)))};
  out.reserve(static_cast<std::size_t>(samples) + 1);
  for (long k = 0; k < samples; ++k) {
    for (long s = 0; s < substeps; ++s)
      y = rk4_step(y, static_cast<double>(k) * sample_s + static_cast<double>(s) * dt, dt, rate);
    out.push_back(observe(Eigen::VectorXd(y.head(n))));
  }
  return out;
}

}  // namespace fowtsim::flexbody
