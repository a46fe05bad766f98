#include "run/run_scene.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <fstream>

#include <fmt/format.h>

#include "beamdyn/beamdyn_run.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/io/deck.hpp"
#include "fowtsim/io/schema.hpp"
#include "run/output_set.hpp"
#include "fowtsim/io/suggest.hpp"
#include "scenes/beam_scene.hpp"
#include "scenes/floating_scene.hpp"
#include "scenes/platform_scene.hpp"
#include "scenes/slender_scene.hpp"
#include "scenes/toy_scene.hpp"

namespace fowtsim::driver {
namespace {

// The top-level keys that make a deck a scene deck, with the scene each one picks, in the order
// run_scene tries them.
constexpr std::array<std::pair<const char*, const char*>, 6> kSceneKeys = {{
    {"beam", "one clamped beam"},
    {"pipe", "one pipe conveying fluid"},
    {"platform_motion", "platform loads on a prescribed motion"},
    {"structure", "floating turbine"},
    {"slender", "a slender body in waves"},
    {"toy_oscillators", "the coupling test problem"},
}};

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// OpenFAST, its modules' and TurbSim's inputs start with a banner line of dashes
// ("------- OpenFAST EXAMPLE INPUT FILE ----"); YAML never starts with four dashes.
bool starts_with_openfast_banner(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    return line.compare(first, 4, "----") == 0;
  }
  return false;
}

[[noreturn]] void throw_not_a_deck(const std::filesystem::path& path, const std::string& detail) {
  throw InputError(
      {"run", std::nullopt, "",
       "give a fowtsim YAML scene deck (inputs/, `fowtsim --help-deck`); a BeamDyn driver input (bd_driver.inp) "
       "runs as is; OpenFAST outputs (.out, .outb) are read by `fowtsim compare`"},
      fmt::format("{}: OpenFAST/TurbSim input is not read by fowtsim run{}", path.string(), detail));
}

// Stops with a clear message before a non-YAML file reaches the YAML parser.
void reject_foreign_input(const std::filesystem::path& path) {
  static const std::array<const char*, 9> kForeign = {".fst", ".dat", ".inp", ".ipt", ".bts", ".wnd",
                                                      ".out", ".outb", ".h5"};
  const std::string ext = lower_extension(path);
  if (std::find(kForeign.begin(), kForeign.end(), ext) != kForeign.end())
    throw_not_a_deck(path, fmt::format(" (a {} file)", ext));
  if (starts_with_openfast_banner(path)) throw_not_a_deck(path, " (it starts with an OpenFAST-style banner line)");
}

// The scene key of the deck's top-level mapping (kSceneKeys); a file that is not YAML, is empty,
// or holds none of them (a component deck such as hydro.yaml) stops here, saying which keys make a
// scene. The deck is loaded once here; the scene then reads it against its schema.
std::string scene_key(const std::filesystem::path& path, const std::vector<std::string>& settings) {
  const std::string ext = lower_extension(path);
  const bool yaml_named = ext == ".yaml" || ext == ".yml";
  io::LoadedDeck loaded;
  try {
    loaded = io::load_deck(path);
    io::apply_settings(loaded, settings);
  } catch (const io::DeckError& e) {
    const bool syntax = std::any_of(e.issues().begin(), e.issues().end(),
                                    [](const io::DeckIssue& i) { return i.kind == io::DeckIssueKind::yaml_syntax; });
    if (syntax && !yaml_named) throw_not_a_deck(path, " (the file is not YAML: " + e.issues().front().to_string() + ")");
    throw;
  }
  const io::DeckNodeKind kind = loaded.root.kind;
  if (kind != io::DeckNodeKind::map && kind != io::DeckNodeKind::null && !yaml_named)
    throw_not_a_deck(path, " (the file is not a YAML mapping of deck keys)");
  std::string keys;
  std::vector<std::string> scene_keys;
  for (const auto& [key, scene] : kSceneKeys) {
    if (loaded.root.find(key)) return key;
    keys += fmt::format("{}`{}` ({})", keys.empty() ? "" : ", ", key, scene);
    scene_keys.emplace_back(key);
  }
  std::string found;
  std::string suggestion;
  if (loaded.root.kind == io::DeckNodeKind::map) {
    for (const io::DeckEntry& e : loaded.root.entries) {
      found += (found.empty() ? "" : ", ") + e.key;
      if (suggestion.empty()) suggestion = io::did_you_mean(e.key, scene_keys, io::LetterCase::ignored);
    }
  }
  const bool empty = kind == io::DeckNodeKind::null || (kind == io::DeckNodeKind::map && loaded.root.entries.empty());
  const std::string holds = empty                            ? "it is empty"
                            : found.empty()                  ? "it holds no mapping of keys"
                                                             : "its top-level keys are " + found;
  const std::string hint = !suggestion.empty() ? suggestion
                           : empty ? "start from a shipped scene deck, e.g. inputs/oc3_hywind/turbine_ntm_12mps_irregular.yaml"
                                   : "a component deck is included from a scene deck (`include: hydro.yaml`), e.g. "
                                     "inputs/oc3_hywind/turbine_ntm_12mps_irregular.yaml";
  throw InputError({"run", std::nullopt, "", hint},
                   fmt::format("{}: no scene to run: a scene deck has one of the top-level keys {}; {}", path.string(), keys,
                               holds));
}

RunReport run_picked_scene(const RunRequest& request, const ProgressCallback& progress) {
  if (is_beamdyn_driver_file(request.deck_path)) {
    if (!request.deck_settings.empty())
      throw InputError({"run", std::nullopt, "--set", "a YAML deck (a beam deck: inputs/beams/rollup.yaml)"},
                       fmt::format("--set {}: a BeamDyn driver input has no deck keys to set", request.deck_settings.front()));
    return run_beamdyn_case(request, progress);
  }
  reject_foreign_input(request.deck_path);
  const std::string scene = scene_key(request.deck_path, request.deck_settings);
  if (scene == "beam") return run_beam_scene(request, progress);
  if (scene == "pipe") return run_pipe_scene(request, progress);
  if (scene == "platform_motion") return run_platform_scene(request, progress);
  if (scene == "structure") return run_floating_scene(request, progress);
  if (scene == "slender") return run_slender_scene(request, progress);
  const io::ValidatedDeck deck = io::read_deck(toy_scene_schema(), request.deck_path, request.deck_settings);
  return run_toy_scene(deck, request, progress);
}

}  // namespace

RunReport run_scene(const RunRequest& request_in, const ProgressCallback& progress) {
  const auto start = std::chrono::steady_clock::now();
  RunReport report = run_picked_scene(resolve_output_names(request_in), progress);
  report.total_wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace fowtsim::driver
