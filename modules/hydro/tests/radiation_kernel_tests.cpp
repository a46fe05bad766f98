// The retardation kernel against closed forms (radiation_kernel.hpp).
#include <cmath>
#include <numbers>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/hydro/radiation_kernel.hpp"

using namespace fowtsim;
using namespace fowtsim::hydro;

TEST_CASE("retardation kernel of a Gaussian damping is the Gaussian's cosine transform", "[verification][hydro]") {
  // B33(ω) = b e^{−ω²} on 0 … 8 rad/s (401 points): K33(t) = (2/π) b (√π/2) e^{−t²/4} = b e^{−t²/4}/√π.
  // The piecewise-linear B errs by h² B''/8 ~ 5e-5 b between nodes; measured ≤ 2.8e-5 b (t = 2 s):
  // bound 3e-4 b. Other entries stay exactly zero.
  const double b = 2.0e5;
  std::vector<double> omega;
  std::vector<Mat6> damping;
  for (int k = 0; k <= 400; ++k) {
    omega.push_back(0.02 * k);
    Mat6 d = Mat6::Zero();
    d(2, 2) = b * std::exp(-omega.back() * omega.back());
    damping.push_back(d);
  }
  const std::vector<double> times = {0.0, 0.5, 1.0, 2.0, 4.0, 8.0, 30.0};
  const std::vector<Mat6> k = retardation_kernel(omega, damping, times);
  for (std::size_t n = 0; n < times.size(); ++n) {
    const double exact = b * std::exp(-times[n] * times[n] / 4.0) / std::sqrt(std::numbers::pi);
    INFO("t = " << times[n] << ": " << k[n](2, 2) << " vs " << exact);
    CHECK(std::abs(k[n](2, 2) - exact) < 3e-4 * b);
    CHECK(k[n](0, 0) == 0.0);
  }
}

TEST_CASE("kernel and added mass are each other's transforms (Ogilvie) for a single-pole body", "[verification][hydro]") {
  // A body with K(t) = c e^{−λt} has B(ω) = ∫_0^∞ K cos(ωt) dt = c λ/(λ² + ω²) and
  // A(ω) − A(∞) = −(1/ω) ∫_0^∞ K sin(ωt) dt = −c/(λ² + ω²). From B tabulated on
  // 0 … 200 rad/s the kernel is rebuilt (the truncated tail, 2cλ/(π·200) ≈ 1.6e-3 c at t = 0) and
  // from the kernel on 0 … 60 s the added mass (trapezoid, Δt 0.01 s). Measured: K(0) 1.6e-3 c,
  // K(2 s) 6.4e-6 c, A(ω) ≤ 3.2e-5 c/λ² (ω = 0.2); bounds ≈ 10× those.
  const double c = 1.0e6, lambda = 0.5;
  std::vector<double> omega;
  std::vector<Mat6> damping;
  for (int k = 0; k <= 40000; ++k) {
    omega.push_back(0.005 * k);
    Mat6 d = Mat6::Zero();
    d(0, 0) = c * lambda / (lambda * lambda + omega.back() * omega.back());
    damping.push_back(d);
  }
  std::vector<double> times;
  for (int n = 0; n <= 6000; ++n) times.push_back(0.01 * n);
  const std::vector<Mat6> k = retardation_kernel(omega, damping, times);
  CHECK(std::abs(k[0](0, 0) - c) < 1.5e-2 * c);
  CHECK(std::abs(k[200](0, 0) - c * std::exp(-lambda * 2.0)) < 1e-4 * c);
  for (const double w : {0.2, 0.5, 1.0, 2.0}) {
    const Mat6 a = added_mass_from_kernel(w, times, k, Mat6::Zero());
    INFO("ω = " << w << ": " << a(0, 0) << " vs " << -c / (lambda * lambda + w * w));
    CHECK(std::abs(a(0, 0) + c / (lambda * lambda + w * w)) < 4e-4 * c / (lambda * lambda));
  }
}
