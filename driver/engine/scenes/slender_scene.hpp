#pragma once
// The slender-body scene (a deck with a top-level `slender`; modules/slender, seed 004): a riser,
// a tower or a spar in a regular wave or a JONSWAP sea, solved in the frequency domain, the time
// domain or both. It writes the profiles along the body — <output>.amplitude.csv in a regular wave,
// <output>.rms.csv in a JONSWAP sea — and, for the time domain, the time series at the deck's
// stations in the usual output formats. Its keys are listed by `fowtsim --help-deck` and in inputs/slender/.
#include "fowtsim/io/schema.hpp"
#include "run/run_types.hpp"

namespace fowtsim::driver {

io::Schema slender_scene_schema();

RunReport run_slender_scene(const RunRequest& request, const ProgressCallback& progress);

}  // namespace fowtsim::driver
