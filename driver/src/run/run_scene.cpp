#include "run/run_scene.hpp"

#include "beamdyn/beamdyn_run.hpp"
#include "scenes/beam_scene.hpp"
#include "scenes/floating_scene.hpp"
#include "scenes/platform_scene.hpp"

#include "fowtsim/io/schema.hpp"
#include "scenes/scene_schema.hpp"
#include "scenes/toy_scene.hpp"

namespace fowtsim::driver {

RunReport run_scene(const RunRequest& request, const ProgressCallback& progress) {
  if (is_beamdyn_driver_file(request.deck_path)) return run_beamdyn_case(request, progress);
  if (is_beam_scene(request.deck_path)) return run_beam_scene(request, progress);
  if (is_platform_scene(request.deck_path)) return run_platform_scene(request, progress);
  if (is_floating_scene(request.deck_path)) return run_floating_scene(request, progress);
  const io::ValidatedDeck deck = io::read_deck(scene_schema(), request.deck_path);
  // The toy oscillators are the only scene until the turbine modules land.
  return run_toy_scene(deck, request, progress);
}

}  // namespace fowtsim::driver
