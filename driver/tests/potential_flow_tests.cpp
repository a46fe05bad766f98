// Potential-flow hydrodynamics (issue 15), the parts that exist: OpenFAST's OC3 WAMIT files read by
// modules/io and their radiation memory by modules/hydro, checked against each other.
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/hydro/radiation_kernel.hpp"
#include "fowtsim/io/wamit_input.hpp"
#include "fowtsim/testing/skip.hpp"

using namespace fowtsim;

TEST_CASE("the OC3 spar's WAMIT damping, as a retardation kernel, gives back its added mass (Ogilvie)",
          "[verification][hydro]") {
  // K(t) from B(ω) of Spar.1 (piecewise linear in ω, zero beyond the table), then
  // A(ω) = A(∞) − (1/ω) ∫ K sin(ωt) dt over 0 … 150 s, against the A(ω) WAMIT tabulated itself for
  // surge, heave and pitch. The table's B ends at a finite frequency and WAMIT's own A and B carry
  // its panel error, so the relation holds to a fraction of the frequency-dependent part
  // A(0) − A(∞), not to rounding. Measured over 0.3–1.8 rad/s: surge ≤ 0.13 %, heave ≤ 0.7 %,
  // pitch ≤ 1.1 % of that span (pitch at 0.3 rad/s); bound 5 %.
  const auto dir = testing::shared_dir_or_skip() / "reference/r-test/glue-codes/openfast/5MW_Baseline/HydroData";
  const io::WamitRadiation r = io::read_wamit_radiation(dir / "Spar.1", {1025.0, 9.80665, 1.0});
  std::vector<double> times;
  for (int n = 0; n <= 3000; ++n) times.push_back(0.05 * n);
  const std::vector<Mat6> kernel = hydro::retardation_kernel(r.frequencies_rad_s, r.damping, times);
  // The kernel decays: after 60 s it is below 1 % of its peak in each diagonal entry (measured
  // ≤ 5.4e-4 of it, surge).
  for (int i : {0, 2, 4}) {
    double peak = 0.0;
    for (const Mat6& k : kernel) peak = std::max(peak, std::abs(k(i, i)));
    CHECK(std::abs(kernel[1200](i, i)) < 0.01 * peak);
  }
  for (std::size_t f = 0; f < r.frequencies_rad_s.size(); f += 5) {
    const double omega = r.frequencies_rad_s[f];
    if (omega < 0.2 || omega > 2.0) continue;  // the band the spar's motions and waves live in
    const Mat6 a = hydro::added_mass_from_kernel(omega, times, kernel, *r.added_mass_infinite_frequency);
    for (int i : {0, 2, 4}) {
      const double span = std::abs((*r.added_mass_zero_frequency)(i, i) - (*r.added_mass_infinite_frequency)(i, i));
      INFO("ω = " << omega << ", mode " << i + 1 << ": " << a(i, i) << " vs WAMIT " << r.added_mass[f](i, i) << " (span "
                  << span << ")");
      CHECK(std::abs(a(i, i) - r.added_mass[f](i, i)) < 0.05 * span);
    }
  }
}
