#include "run/validate_deck.hpp"

#include "fowtsim/io/deck.hpp"
#include "fowtsim/io/schema.hpp"
#include "scenes/beam_scene.hpp"
#include "scenes/floating_scene.hpp"
#include "scenes/platform_scene.hpp"
#include "scenes/slender_scene.hpp"
#include "scenes/toy_scene.hpp"

namespace fowtsim::driver {

std::string validate_scene_deck(const std::filesystem::path& path) {
  io::LoadedDeck loaded = io::load_deck(path);
  const std::string hash = loaded.hash;
  // The scene a deck picks by its top-level key, in run_scene's order.
  const io::DeckNode& root = loaded.root;
  if (root.find("beam")) {
    io::validate(beam_scene_schema(), std::move(loaded));
  } else if (root.find("pipe")) {
    io::validate(pipe_scene_schema(), std::move(loaded));
  } else if (root.find("platform_motion")) {
    io::validate(platform_scene_schema(), std::move(loaded));
  } else if (root.find("structure")) {
    const io::ValidatedDeck deck = io::validate(floating_scene_schema(), std::move(loaded));
    const FloatingScene scene(deck, FloatingScene::SetUp::check);  // its constructor applies the rules
  } else if (root.find("slender")) {
    io::validate(slender_scene_schema(), std::move(loaded));
  } else {
    io::validate(toy_scene_schema(), std::move(loaded));
  }
  return hash;
}

}  // namespace fowtsim::driver
