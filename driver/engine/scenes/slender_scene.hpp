#pragma once
// The slender-body scene (a deck with a top-level `slender`; modules/slender, seed 004): a riser,
// a tower or a spar in a regular wave or a JONSWAP sea, solved in the frequency domain, the time
// domain or both. It writes the profiles along the body — <output>.amplitude.csv in a regular wave,
// <output>.rms.csv in a JONSWAP sea — and, for the time domain, the time series at the deck's
// stations in the usual output formats. Its keys are listed by `fowtsim --help-deck` and in inputs/slender/.
// The frequency domain is solved before the loop; the time domain is stepped by the run loop
// (scenes/slender_time_domain.hpp: the module's RK4 step, the sea in blocks, the TD profiles
// accumulated step by step), its one SlenderTimeState is what checkpoints write and restarts read,
// and the profile table, complete only with the last step, is written after the loop (an
// interrupted or failed run leaves none).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "decks/slender_deck.hpp"
#include "fowtsim/io/schema.hpp"
#include "run/run_types.hpp"

namespace fowtsim::driver {

io::Schema slender_scene_schema();

// A slender deck read and checked, with its time domain's step and span (simulation.dt_s, t_max_s).
struct SlenderCase {
  SlenderDeck deck;
  double dt_s = 0.0, t_max_s = 0.0;
};
SlenderCase read_slender_case(const io::ValidatedDeck& deck, std::optional<double> t_max_override = std::nullopt);
// The same from a file, with --set style settings ("sea.seed=3").
SlenderCase read_slender_case(const std::filesystem::path& path, const std::vector<std::string>& settings = {});

RunReport run_slender_scene(const RunRequest& request, const ProgressCallback& progress);

}  // namespace fowtsim::driver
