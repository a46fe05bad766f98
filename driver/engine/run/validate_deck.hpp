#pragma once
// A scene deck checked as `fowtsim run` reads it, without running it: loaded with its includes,
// validated against its scene's schema, and a floating-turbine deck read by the scene itself, so
// the rules across keys of every section (pitch limits, rotor geometry, sea, …) apply as in a run.
// Only the turbulent wind field is not generated (FloatingScene::SetUp::check): its parameters are
// checked, its seconds of generation are left to the run. Beam, platform and toy decks are checked
// against their schema (their scenes read the deck as they run). A sweep checks every case deck
// with it before anything runs.
#include <filesystem>
#include <string>

namespace fowtsim::driver {

// Returns the deck hash (io::LoadedDeck::hash, what a run records as deck_hash). Throws
// io::DeckError (every schema problem, file:line:col) or InputError (a scene's rule, file:line).
std::string validate_scene_deck(const std::filesystem::path& deck);

}  // namespace fowtsim::driver
