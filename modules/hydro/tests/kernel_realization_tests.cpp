// The state-space alternative to the radiation convolution (kernel_realization.hpp): Kung's
// realisation must give back a kernel that is a sum of exponentials, poles and all.
#include <cmath>
#include <cstdio>
#include <complex>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/hydro/kernel_realization.hpp"

using namespace fowtsim::hydro;

TEST_CASE("Kung's realisation recovers a kernel made of a damped oscillation and a decay", "[unit][hydro]") {
  // K(t) = 3 e^{−0.2t} cos(1.1t) + 1.5 e^{−0.7t}: order 3 exactly (one pair, one real pole).
  const auto exact = [](double t) { return 3.0 * std::exp(-0.2 * t) * std::cos(1.1 * t) + 1.5 * std::exp(-0.7 * t); };
  std::vector<double> samples;
  for (int k = 0; k < 300; ++k) samples.push_back(exact(0.1 * k));
  const ExponentialFit fit = fit_exponentials(samples, 0.1, 1e-9, 10);
  // Noise-free data: order 3 reproduces it to round-off (measured below 1e-12 relative).
  std::printf("Kung realisation of a three-pole kernel: relative error %.2e\n", fit.relative_error);
  CHECK(fit.relative_error < 1e-9);
  CHECK(fit.order == 3);
  bool pair = false, decay = false;
  for (const ExponentialTerm& t : fit.terms) {
    if (std::abs(t.pole - std::complex<double>(-0.2, 1.1)) < 1e-8) {
      pair = true;
      CHECK(t.weight == 2.0);
      CHECK(std::abs(t.residue - 1.5) < 1e-8);  // 3 cos = 2 Re(1.5 e^{i1.1t})
    }
    if (std::abs(t.pole - std::complex<double>(-0.7, 0.0)) < 1e-8) {
      decay = true;
      CHECK(std::abs(t.residue - 1.5) < 1e-8);
    }
    CHECK(t.pole.real() < 0.0);  // stable by construction
  }
  CHECK(pair);
  CHECK(decay);
  for (double t : {0.0, 0.37, 5.0, 29.9}) CHECK(evaluate(fit, t) == Approx(exact(t)).margin(1e-9));
}

TEST_CASE("a zero kernel fits to nothing, and too few samples are refused", "[unit][hydro]") {
  const std::vector<double> zeros(50, 0.0);
  const ExponentialFit fit = fit_exponentials(zeros, 0.1, 0.01, 10);
  CHECK(fit.terms.empty());
  CHECK(fit.relative_error == 0.0);
  CHECK(evaluate(fit, 1.0) == 0.0);
  CHECK_THROWS(fit_exponentials(std::vector<double>(5, 1.0), 0.1, 0.01, 10));
}
