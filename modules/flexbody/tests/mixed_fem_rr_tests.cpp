// Seed Sec. 5.5, Table 1: the mixed FEM–Rayleigh–Ritz beam (eq. 19) and its Guyan / Craig–Bampton
// reductions, 2nd and 4th frequencies and mode shapes against the clamped-free solution (eq. 32).
#include "fowtsim/flexbody/verification.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

using namespace fowtsim::flexbody::verification;

// The model and the error measures: verification.hpp mixed_case_errors (Sec. 5.5 uses "the beam of
// subsection 5.1": uniform, L 100 m, EI 2e12 N m², m 9e3 kg/m; for a uniform beam the relative
// errors do not depend on these values). `fowtsim verify flexbody` runs the same rows.

TEST_CASE("Table 1 of Sec. 5.5: mixed FEM-RR, Guyan and Craig-Bampton vs the seed", "[verification]") {
  // seed_table1: δf_2, δf_4, δu_2, δu_4 of Table 1 [%]. "GY2-RR4c" is split "at 0.4% of its length"
  // in the text, but the seed's numbers are those of a split at 0.4 L (40 %): measured
  // 0.14/12.86/0.05/9.54 at 0.4 L against 0.00/0.003/0.001/0.27 at 0.004 L (a 0.4 m Guyan stub is
  // exact and b's modes are nearly the full beam's). Both splits are run; the seed's values are
  // compared with 0.4 L.
  std::printf("Table 1 (Sec. 5.5), errors in %%: ours [seed]\n");
  for (const auto& [c, seed] : seed_table1()) {
    const MixedErrors e = mixed_case_errors(c);
    const double ours[4] = {100 * e.f[0], 100 * e.f[1], 100 * e.u[0], 100 * e.u[1]};
    std::printf("%-18s df2 %7.3f [%6.2f]  df4 %7.3f [%6.2f]  du2 %6.3f [%5.2f]  du4 %6.3f [%5.2f]\n",
                c.name.c_str(), ours[0], seed[0], ours[1], seed[1], ours[2], seed[2], ours[3], seed[3]);
    INFO(c.name);
    // Every model here is conforming (FEM, Guyan/CB subspaces and b's shapes are all admissible
    // for the clamped-free beam), so Rayleigh–Ritz bounds the frequencies from above; 1e-9 is
    // eigen-solver rounding. The seed's negative −0.01/−0.03 % cannot come from such a model: they
    // are its discretisation/extraction offsets (50 integration sections, time-domain Newmark).
    CHECK(e.f[0] > -1e-9);
    CHECK(e.f[1] > -1e-9);
    // Agreement with the seed within 0.1 percentage point + 8 % of its value: 0.1 covers its
    // 2-decimal rounding and the ±0.05 offsets above (FEM50-RR4, CB: ours +0.001/+0.035,
    // +0.006/+0.18); 8 % covers the largest relative gap measured, 6.7 % on GY2-RR4c δf_4
    // (12.86 vs 12.06) and 2.5 % on GY2-RR2 δf_4 (51.35 vs 50.08) — the seed's frequencies are
    // systematically a little lower, consistent with its coarser spanwise integration; not traced.
    for (int k = 0; k < 4; ++k) CHECK(std::abs(ours[k] - seed[k]) < 0.1 + 0.08 * std::abs(seed[k]));
  }
}

TEST_CASE("GY2-RR4 split at 0.4 % of the length: a Guyan stub is exact", "[verification]") {
  // The text's split. The 0.4 m FEM stub is rigid to within (0.004)^2 of the beam and b's four
  // eq. 32 modes (length 0.996 L) nearly span the full beam's first four: measured δf_2 2.5e-8,
  // δf_4 3.2e-5, δu_4 2.7e-3 (relative) — bounds ~3×.
  const MixedErrors e = mixed_case_errors({"GY2-RR4 (0.004 L)", 0.004, 50, 0, 4});
  CHECK(e.f[0] > -1e-9);
  CHECK(e.f[0] < 1e-7);
  CHECK(e.f[1] < 1e-4);
  CHECK(e.u[1] < 1e-2);
}
