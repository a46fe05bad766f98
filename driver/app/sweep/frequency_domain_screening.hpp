#pragma once
// `fowtsim sweep SPEC --frequency-domain`: every case of the spec screened in the frequency domain
// (scenes/floating_screening.hpp) from its deck — the base deck with the case's keys set — before
// any time-domain run: one row per case with the standard deviations of the screened channels, the
// cases ranked by the tower-base fore-aft moment's (TwrBsMyt), the largest first. A case the
// screening cannot take (an external controller, a sea without a spectrum, a balance that does not
// converge) keeps its row with the reason. Writes OUTPUT_DIR/frequency_domain_screening.csv.
#include <cstdio>
#include <vector>

#include "sweep/case_expansion.hpp"
#include "sweep/sweep_spec.hpp"

namespace fowtsim::driver::sweep {

// Returns 0 when every case was screened, 1 otherwise.
int screen_sweep(std::FILE* out, const SweepSpec& spec, const std::vector<SweepCase>& cases);

}  // namespace fowtsim::driver::sweep
