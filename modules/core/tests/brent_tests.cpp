// Brent's root finder against roots known in closed form or to full precision.
#include <cmath>

#include <catch2/catch.hpp>

#include "fowtsim/core/brent.hpp"

using namespace fowtsim;

TEST_CASE("Brent finds known roots to its tolerance", "[unit][brent]") {
  constexpr double kTolerance = 1e-12;
  int calls = 0;
  const auto cubic = [&calls](double x) {
    ++calls;
    return x * x * x - 2.0;
  };
  const double r = brent_root(cubic, 0.0, 2.0, cubic(0.0), cubic(2.0), kTolerance, 200);
  // Stops within 2 ε |x| + tolerance/2 of the root: 1e-12 bounds both for x ≈ 1.26.
  CHECK(std::abs(r - std::cbrt(2.0)) < kTolerance);
  CHECK(calls < 20);  // superlinear: bisection alone would need 41 halvings of 2 to reach 1e-12

  // cos x = x (the Dottie number, 0.73908513321516064...), bracket given high end first.
  const auto fixed_point = [](double x) { return std::cos(x) - x; };
  const double d = brent_root(fixed_point, 1.0, 0.0, fixed_point(1.0), fixed_point(0.0), kTolerance, 200);
  CHECK(std::abs(d - 0.73908513321516064) < kTolerance);  // reference to 17 digits
}

TEST_CASE("Brent returns a bracket end that is already a root", "[unit][brent]") {
  const auto line = [](double x) { return x - 1.0; };
  CHECK(brent_root(line, 1.0, 3.0, 0.0, 2.0, 1e-12, 200) == 1.0);  // f = 0 there: exact
}
