// The dispersion relation ω² = g k tanh(k h) (verification against high-precision references).
#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/waves/dispersion.hpp"

using namespace fowtsim;
using namespace fowtsim::waves;

namespace {
constexpr double g = 9.80665;
constexpr double eps = std::numeric_limits<double>::epsilon();
}  // namespace

TEST_CASE("wavenumber matches 60-digit references from shallow to deep water", "[verification][waves]") {
  // Reference: Newton on x tanh x = ω² h / g in Python's decimal module at 60 significant digits
  // (mpmath absent), g = 9.80665: tests/references/dispersion.py run with /usr/bin/python3.
  struct Case {
    double omega, depth, k;
  };
  const Case cases[] = {
      {0.05, 10, 5.05119619486622491083e-3},                 // kh = 0.0505 (shallow)
      {0.1, 5, 1.42930165241461036062e-2},                   // kh = 0.0715
      {0.2, 20, 1.44779653548505948474e-2},                  // kh = 0.290
      {0.3, 1, 9.59457654983588377008e-2},                   // kh = 0.0959
      {0.01, 4000, 5.08363175099161628603e-5},               // kh = 0.203
      {3.0, 0.5, 1.46753478990615811205e+0},                 // kh = 0.734
      {0.5, 50, 2.85926064616712643628e-2},                  // kh = 1.43 (intermediate)
      {1.0, 30, 1.02410026138562051316e-1},                  // kh = 3.07
      {2.0, 20, 4.07886552157145819695e-1},                  // kh = 8.16
      {0.6283185307179586, 320, 4.02567824943971957748e-2},  // kh = 12.9 (OC3 depth, T = 10 s)
      {1.0, 320, 1.01971621297792824257e-1},                 // kh = 32.6 (deep)
      {2.0, 320, 4.07886485191171297028e-1},                 // kh = 131
      {6.0, 320, 3.67097836672054167325e+0},                 // kh = 1175
      {12.566370614359172, 320, 1.61027129975506124852e+1},  // kh = 5153
  };
  for (const Case& c : cases) {
    const double k = wavenumber(c.omega, c.depth, g);
    INFO("omega " << c.omega << " depth " << c.depth << " k " << k << " ref " << c.k);
    // Tolerance 1e-12 relative (issue); measured ≤ 4.4e-16 (2 ulp).
    CHECK(std::abs(k - c.k) <= 1e-12 * c.k);
  }
}

TEST_CASE("wavenumber solves the dispersion relation to machine precision everywhere", "[unit][waves]") {
  // Residual of x tanh x = y on a log grid of y = ω² h / g over 1e-8 … 1e6: at most a few ulps of y
  // (the residual's own round-off is ~2 eps y).
  double worst = 0.0;
  for (int i = 0; i <= 280; ++i) {
    const double y = std::pow(10.0, -8.0 + 0.05 * i);
    const double depth = 50.0;
    const double omega = std::sqrt(y * g / depth);
    const double x = wavenumber(omega, depth, g) * depth;
    const double yy = omega * omega * depth / g;
    worst = std::max(worst, std::abs(x * std::tanh(x) - yy) / yy);
  }
  CHECK(worst <= 4.0 * eps);
}

TEST_CASE("wavenumber has the deep- and shallow-water limits", "[unit][waves]") {
  const double inf = std::numeric_limits<double>::infinity();
  // Deep: h = +inf is exactly ω²/g; kh ≥ 19 (tanh = 1 in double) is ω²/g to round-off.
  CHECK(wavenumber(0.7, inf, g) == deep_water_wavenumber(0.7, g));
  CHECK(wavenumber(2.0, 320.0, g) == Approx(4.0 / g).epsilon(4 * eps));
  // Shallow: x tanh x = y gives x = √y (1 + y/6 + O(y²)); at y = 1e-6 the O(y²) rest is ~1e-12.
  const double depth = 10.0, y = 1e-6, omega = std::sqrt(y * g / depth);
  CHECK(wavenumber(omega, depth, g) * depth == Approx(std::sqrt(y) * (1.0 + y / 6.0)).epsilon(1e-11));
  CHECK(wavenumber(0.0, depth, g) == 0.0);
  // Monotone in ω and decreasing in depth.
  CHECK(wavenumber(0.5, 20.0, g) < wavenumber(0.51, 20.0, g));
  CHECK(wavenumber(0.5, 20.0, g) > wavenumber(0.5, 21.0, g));
}

TEST_CASE("wavenumber rejects invalid arguments", "[unit][waves]") {
  CHECK_THROWS_AS(wavenumber(1.0, -5.0, g), InputError);
  CHECK_THROWS_AS(wavenumber(1.0, 0.0, g), InputError);
  CHECK_THROWS_AS(wavenumber(-1.0, 10.0, g), InputError);
  CHECK_THROWS_AS(wavenumber(std::nan(""), 10.0, g), InputError);
  CHECK_THROWS_AS(wavenumber(1.0, 10.0, 0.0), InputError);
}
