// JONSWAP / Pierson–Moskowitz spectra: normalisation m0 = Hs²/16, peak, IEC default γ.
#include <cmath>
#include <numbers>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/waves/spectrum.hpp"
#include "fowtsim/waves/wave_params.hpp"

using namespace fowtsim;
using namespace fowtsim::waves;

namespace {
constexpr double kPi = std::numbers::pi;

// m0 by the trapezoidal rule on a uniform ω grid (independent of the module's ν-quadrature).
double m0_trapezoid(double hs, double tp, double gamma, double omega_max, int n) {
  const double c = jonswap_normalisation(gamma);
  const double h = omega_max / n;
  double sum = 0.0;
  for (int i = 1; i < n; ++i) sum += jonswap_density(i * h, hs, tp, gamma, c);
  return sum * h;  // S(0) = 0; S(omega_max) ~ 0
}
}  // namespace

TEST_CASE("JONSWAP normalisation matches an independent high-resolution quadrature", "[verification][waves]") {
  // Reference C(γ) = 1/(5 I(γ)) by numpy composite Simpson with 4e5 panels per side (unchanged at
  // 2e5 to all 16 digits), tests/references/jonswap_normalisation.py. Our 8192-panel Simpson
  // split at the kink: measured ≤ 1.6e-15 relative; tolerance 2e-14.
  CHECK(jonswap_normalisation(1.0) == 1.0);
  CHECK(jonswap_normalisation(2.0) == Approx(0.80281017653891).epsilon(2e-14));
  CHECK(jonswap_normalisation(3.3) == Approx(0.6557598030897296).epsilon(2e-14));
  CHECK(jonswap_normalisation(5.0) == Approx(0.5380898642551063).epsilon(2e-14));
  CHECK(jonswap_normalisation(7.0) == Approx(0.4494040201334248).epsilon(2e-14));
  // DNV-RP-C205's closed form 1 − 0.287 ln γ (used by HydroDyn) is within 0.3 % at γ = 3.3.
  CHECK(jonswap_normalisation(3.3) == Approx(1.0 - 0.287 * std::log(3.3)).epsilon(3e-3));
}

TEST_CASE("spectra integrate to m0 = Hs^2/16", "[verification][waves]") {
  // Trapezoid on 4e5 points to ω = 40 rad/s: the ω⁻⁵ tail beyond holds (ωp/40)⁴/5 ≈ 5e-8 of m0
  // (Tp = 10 s) and the grid error is smaller still; tolerance 1e-6.
  for (double gamma : {1.0, 2.0, 3.3, 5.0}) {
    INFO("gamma " << gamma);
    CHECK(m0_trapezoid(6.0, 10.0, gamma, 40.0, 400000) == Approx(36.0 / 16.0).epsilon(1e-6));
  }
  CHECK(m0_trapezoid(1.8, 6.1, default_peak_shape(1.8, 6.1), 60.0, 400000) == Approx(1.8 * 1.8 / 16.0).epsilon(1e-6));
}

TEST_CASE("spectra peak at 2 pi / Tp and PM is JONSWAP with gamma 1", "[unit][waves]") {
  const double tp = 10.0, wp = 2.0 * kPi / tp;
  for (double gamma : {1.0, 3.3}) {
    const double c = jonswap_normalisation(gamma);
    double best = 0.0, best_omega = 0.0;
    for (int i = 1; i < 20000; ++i) {
      const double om = 1e-4 * i;
      const double s = jonswap_density(om, 6.0, tp, gamma, c);
      if (s > best) best = s, best_omega = om;
    }
    CHECK(std::abs(best_omega - wp) <= 1e-4);  // grid step
  }
  CHECK(pierson_moskowitz_density(0.7, 6.0, 10.0) == jonswap_density(0.7, 6.0, 10.0, 1.0));
  CHECK(jonswap_density(0.0, 6.0, 10.0, 3.3) == 0.0);
  CHECK(jonswap_density(1e-300, 6.0, 10.0, 3.3) == 0.0);  // no overflow near ω = 0
  CHECK_THROWS_AS(jonswap_normalisation(0.9), InputError);
}

TEST_CASE("default peak shape follows IEC 61400-3", "[unit][waves]") {
  CHECK(default_peak_shape(4.0, 7.0) == 5.0);                          // Tp/√Hs = 3.5
  CHECK(default_peak_shape(4.0, 7.2) == 5.0);                          // = 3.6, boundary
  CHECK(default_peak_shape(4.0, 8.0) == Approx(std::exp(5.75 - 1.15 * 4.0)));  // = 4
  CHECK(default_peak_shape(4.0, 10.0) == Approx(std::exp(5.75 - 5.75)));       // = 5 → 1
  CHECK(default_peak_shape(4.0, 12.0) == 1.0);                         // = 6
  CHECK(default_peak_shape(0.0, 12.0) == 1.0);                         // calm
  // The seed's load cases (seed 000 Table 4.2): typical Hs 1.8 m, Tp 6.1 s → Tp/√Hs = 4.547;
  // extreme Hs 11.3 m, Tp 14.4 s → 4.284.
  CHECK(default_peak_shape(1.8, 6.1) == Approx(std::exp(5.75 - 1.15 * 6.1 / std::sqrt(1.8))));
  CHECK(default_peak_shape(1.8, 6.1) == Approx(1.684).epsilon(1e-3));
  CHECK(default_peak_shape(11.3, 14.4) == Approx(2.279).epsilon(1e-3));
}
