// Rayleigh–Ritz eigenproblems assembled from the module's integrals, against analytic beam theory
// (verification.hpp; `fowtsim verify flexbody` runs the top-mass and buckling checks too).
#include "fowtsim/flexbody/verification.hpp"

#include <catch2/catch.hpp>

using namespace fowtsim::flexbody::verification;

TEST_CASE("RR frequencies of the clamped-free beam with polynomial shapes vs β_n L", "[verification]") {
  const std::vector<Checked> w = monomial_frequencies(4, 3);
  // RR bounds from above; errors measured with x̃²..x̃⁵: 1.54e-6, 5.6e-3, 2.67e-2 — the bounds are
  // those ×~3 (mode 3 is the highest a 4-term space resolves at all).
  const double bound[3] = {5e-6, 2e-2, 8e-2};
  for (int n = 1; n <= 3; ++n) {
    const Checked& c = w[static_cast<std::size_t>(n - 1)];
    INFO("mode " << n << ": RR " << c.value << " rad/s, exact " << c.exact << ", rel. error " << c.relative_error());
    CHECK(c.value >= c.exact * (1 - 1e-12));  // Rayleigh–Ritz is an upper bound
    CHECK(c.relative_error() < bound[n - 1]);
  }
}

TEST_CASE("Eq. 32 modes with a top mass give the top-mass beam's frequencies", "[verification]") {
  // M_t = 0.5 M: RR on the first 4 top-mass modes with the tip mass added to M_q (u_j(L) = 1)
  // reproduces ω_j = (β_j/L)² sqrt(EI/m) of eq. 32's frequency equation — exact, as these modes are
  // the eigenfunctions; tolerance 1e-10 covers quadrature (1e-13) and eigen-solver rounding.
  for (const Checked& c : top_mass_mode_frequencies(0.5, 4)) CHECK(c.value == Approx(c.exact).epsilon(1e-10));
}

TEST_CASE("Geometric stiffness of eq. 26 buckles the column at Euler's and Greenhill's loads", "[verification]") {
  // K_q + λ K^T(unit load) is singular at the critical load λ, shapes x̃²..x̃⁶.
  const Buckling b = column_buckling(5);
  // Top (dead) load: P_cr = π² EI / (4L²). RR upper bound; measured +8.6e-9 (bound ~3×).
  CHECK(b.euler.relative_error() < 3e-8);
  CHECK(b.euler.relative_error() > -1e-12);
  // Self weight: critical total weight (mgL)_cr = 7.8373 EI/L² (Greenhill; Timoshenko & Gere,
  // Theory of elastic stability, §2.13). Tolerance: the 5-digit constant.
  CHECK(b.greenhill == Approx(7.8373).epsilon(5e-5));
}
