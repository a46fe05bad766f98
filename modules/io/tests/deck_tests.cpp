// Loading YAML decks into DeckNode trees: source locations, include merging, load errors and
// the deck hash.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fowtsim/io/deck.hpp"
#include "fowtsim/testing/skip.hpp"

namespace {

using fowtsim::io::DeckError;
using fowtsim::io::DeckIssueKind;
using fowtsim::io::DeckNodeKind;
using fowtsim::io::load_deck;
namespace fs = std::filesystem;

// Writes `text` to `file`, dropping the newline right after R"( so that the first line of the
// literal is line 1 of the file.
fs::path write(const fs::path& file, std::string text) {
  if (!text.empty() && text.front() == '\n') text.erase(0, 1);
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

struct Failure {
  std::string message;                         // DeckError::what()
  std::vector<fowtsim::io::DeckIssue> issues;  // DeckError::issues()
};

// Runs `load`, which must throw a DeckError, and returns what it reported.
template <class Load>
Failure load_error(Load load) {
  try {
    load();
  } catch (const DeckError& error) {
    return {error.what(), error.issues()};
  }
  FAIL("no DeckError thrown");
  return {};
}

}  // namespace

TEST_CASE("load_deck keeps key order, scalar text, key paths and 1-based locations",
          "[unit][deck]") {
  // Intent: the tree mirrors the file, with every node and key located where it is written.
  const auto dir = fowtsim::testing::scratch_dir("deck_basic");
  const auto file = write(dir / "scene.yaml", R"(
simulation:
  t_max_s: 600
  dt_s: 0.05
channels: [RotSpeed, "GenPwr"]
empty:
)");
  const auto deck = load_deck(file);
  const auto& root = deck.root;
  REQUIRE(root.kind == DeckNodeKind::map);
  REQUIRE(root.entries.size() == 3);
  CHECK(root.entries[0].key == "simulation");
  CHECK(root.entries[1].key == "channels");
  CHECK(root.entries[2].key == "empty");

  const auto* dt = root.find("simulation")->find("dt_s");
  REQUIRE(dt != nullptr);
  CHECK(dt->kind == DeckNodeKind::scalar);
  CHECK(dt->scalar == "0.05");
  CHECK(dt->path == "simulation.dt_s");
  CHECK(dt->location.to_string() == file.string() + ":3:9");
  CHECK(root.find("simulation")->entries[1].key_location.to_string() == file.string() + ":3:3");

  const auto* channels = root.find("channels");
  REQUIRE(channels->items.size() == 2);
  CHECK(channels->items[1].scalar == "GenPwr");
  CHECK(channels->items[1].path == "channels[1]");
  CHECK(channels->items[1].location.column == 22);

  // An empty value is located at its key: yaml-cpp marks it on the next line.
  CHECK(root.find("empty")->kind == DeckNodeKind::null);
  CHECK(root.find("empty")->location.line == 5);
  CHECK(root.find("missing") == nullptr);
}

TEST_CASE("include: own keys override, nested mappings merge, sequences are replaced",
          "[unit][deck]") {
  // Intent: the merge rule of DESIGN.md §5, with the including file winning.
  const auto dir = fowtsim::testing::scratch_dir("deck_include_merge");
  write(dir / "turbine.yaml", R"(
rotor:
  radius_m: 63
  blades: 3
  hub:
    mass_kg: 56780
    height_m: 90
tower_heights_m: [0, 40, 80]
)");
  const auto scene = write(dir / "scene.yaml", R"(
include: turbine.yaml
rotor:
  blades: 2
  hub:
    mass_kg: 60000
tower_heights_m: [0, 87.6]
)");
  const auto root = load_deck(scene).root;
  const auto* rotor = root.find("rotor");
  CHECK(rotor->find("radius_m")->scalar == "63");  // kept from the include
  CHECK(rotor->find("blades")->scalar == "2");     // overridden
  CHECK(rotor->find("hub")->find("mass_kg")->scalar == "60000");
  CHECK(rotor->find("hub")->find("height_m")->scalar == "90");  // nested merge keeps it
  CHECK(root.find("tower_heights_m")->items.size() == 2);       // replaced, not appended
  CHECK(root.find("include") == nullptr);
  CHECK(rotor->find("hub")->find("height_m")->path == "rotor.hub.height_m");
}

TEST_CASE("a value from an included file is located in that file", "[unit][deck]") {
  // Intent: errors about included values must point to the component file, not the scene.
  const auto dir = fowtsim::testing::scratch_dir("deck_include_location");
  const auto turbine = write(dir / "turbine.yaml", R"(
rotor:
  radius_m: 63
)");
  const auto scene = write(dir / "scene.yaml", R"(
include: turbine.yaml
rotor:
  blades: 3
)");
  const auto root = load_deck(scene).root;
  const auto* radius = root.find("rotor")->find("radius_m");
  CHECK(radius->location.to_string() == turbine.string() + ":2:13");
  CHECK(root.find("rotor")->find("blades")->location.to_string() == scene.string() + ":3:11");
}

TEST_CASE("include paths are relative to the including file", "[unit][deck]") {
  // Intent: a component file can include its own neighbours wherever the scene is.
  const auto dir = fowtsim::testing::scratch_dir("deck_include_relative");
  write(dir / "components" / "airfoils.yaml", "airfoil_count: 8\n");
  write(dir / "components" / "turbine.yaml", "include: airfoils.yaml\nblades: 3\n");
  const auto scene = write(dir / "scenes" / "scene.yaml", "include: ../components/turbine.yaml\n");
  const auto deck = load_deck(scene);
  CHECK(deck.root.find("airfoil_count")->scalar == "8");
  CHECK(deck.root.find("blades")->scalar == "3");
  REQUIRE(deck.files.size() == 3);
  CHECK(deck.files[2] == (dir / "components" / "airfoils.yaml").lexically_normal());
}

TEST_CASE("include inside a nested mapping places the included keys under it", "[unit][deck]") {
  // Intent: component files hold one component at their top level and can be mounted anywhere.
  const auto dir = fowtsim::testing::scratch_dir("deck_include_nested");
  write(dir / "spar.yaml", "draft_m: 120\nmass_kg: 7466330\n");
  const auto scene = write(dir / "scene.yaml", R"(
platform:
  include: spar.yaml
  mass_kg: 7500000
)");
  const auto deck = load_deck(scene);
  const auto* platform = deck.root.find("platform");
  CHECK(platform->find("draft_m")->scalar == "120");
  CHECK(platform->find("draft_m")->path == "platform.draft_m");
  CHECK(platform->find("mass_kg")->scalar == "7500000");
}

TEST_CASE("a list of includes merges in order, later files overriding earlier ones",
          "[unit][deck]") {
  // Intent: `include: [a, b]` behaves like including a, then b.
  const auto dir = fowtsim::testing::scratch_dir("deck_include_list");
  write(dir / "a.yaml", "x: 1\ny: 1\n");
  write(dir / "b.yaml", "y: 2\nz: 2\n");
  const auto root = load_deck(write(dir / "scene.yaml", "include: [a.yaml, b.yaml]\n")).root;
  CHECK(root.find("x")->scalar == "1");
  CHECK(root.find("y")->scalar == "2");
  CHECK(root.find("z")->scalar == "2");
}

TEST_CASE("a YAML syntax error is reported with file:line:col", "[unit][deck]") {
  // Intent: the parser's position reaches the user, 1-based.
  const auto dir = fowtsim::testing::scratch_dir("deck_syntax");
  const auto file = write(dir / "bad.yaml", R"(
simulation:
  channels: [RotSpeed, GenPwr
  t_max_s: 10
)");
  const auto error = load_error([&] { load_deck(file); });
  REQUIRE(error.issues.size() == 1);
  CHECK(error.issues[0].kind == DeckIssueKind::yaml_syntax);
  CHECK(error.issues[0].location.file == file.string());
  // yaml-cpp reports 0-based (2, 9) here: where it gave up on the unclosed flow sequence.
  CHECK(error.issues[0].location.line == 3);
  CHECK(error.issues[0].location.column == 10);
  CHECK_THAT(error.message,
             Catch::Contains(file.string() + ":") && Catch::Contains("invalid YAML"));
}

TEST_CASE("a missing include file is reported at the include", "[unit][deck]") {
  // Intent: the message names the including file:line:col and the path that was tried.
  const auto dir = fowtsim::testing::scratch_dir("deck_include_missing");
  const auto scene = write(dir / "scene.yaml", R"(
rotor:
  include: [blade.yaml, hub.yaml]
)");
  write(dir / "blade.yaml", "length_m: 61.5\n");
  const auto error = load_error([&] { load_deck(scene); });
  REQUIRE(error.issues.size() == 1);
  CHECK(error.issues[0].kind == DeckIssueKind::file_unreadable);
  CHECK_THAT(error.message,
             Catch::Contains(scene.string() + ":2:25: rotor.include[1]: cannot open " +
                             (dir / "hub.yaml").string()));
}

TEST_CASE("a directory named as an include is reported as a directory at the include", "[unit][deck]") {
  // Intent: "no such file" would send the user looking for a missing file that is there as a folder.
  const auto dir = fowtsim::testing::scratch_dir("deck_include_directory");
  std::filesystem::create_directories(dir / "hub.yaml");
  write(dir / "scene.yaml", "include: [hub.yaml]\n");
  const auto error = load_error([&] { load_deck(dir / "scene.yaml"); });
  REQUIRE(error.issues.size() == 1);
  CHECK_THAT(error.message, Catch::Contains((dir / "scene.yaml").string() + ":1:11: include[0]: cannot open") &&
                                Catch::Contains("hub.yaml (it is a directory, not a file)"));
}

TEST_CASE("a deck file holding two YAML documents is refused where the second starts", "[unit][deck]") {
  // Intent: YAML::Load keeps the first document and drops the rest unread, valid or not; a deck
  // is one document, so a second one is an error at its "---" line (with or without a leading one).
  const auto dir = fowtsim::testing::scratch_dir("deck_two_documents");
  write(dir / "two.yaml", "a: 1\n---\nb: {c: -5, bogus: 1}\n");
  auto error = load_error([&] { load_deck(dir / "two.yaml"); });
  REQUIRE(error.issues.size() == 1);
  CHECK_THAT(error.message, Catch::Contains((dir / "two.yaml").string() + ":2:1: invalid YAML: 2 YAML documents"));
  write(dir / "marked.yaml", "# a comment\n---\na: 1\n---\n");
  error = load_error([&] { load_deck(dir / "marked.yaml"); });
  CHECK_THAT(error.message, Catch::Contains((dir / "marked.yaml").string() + ":4:1: invalid YAML: 2 YAML documents"));
  // One document, explicitly opened and closed, is a deck.
  write(dir / "one.yaml", "---\na: 1\n...\n");
  CHECK(load_deck(dir / "one.yaml").root.find("a") != nullptr);
}

TEST_CASE("a missing deck file is reported", "[unit][deck]") {
  // Intent: a wrong path on the command line gives a DeckError, not a crash or an empty deck.
  const auto dir = fowtsim::testing::scratch_dir("deck_missing");
  const auto error = load_error([&] { load_deck(dir / "nowhere.yaml"); });
  CHECK(error.issues[0].kind == DeckIssueKind::file_unreadable);
  CHECK_THAT(error.message, Catch::Contains("nowhere.yaml"));
}

TEST_CASE("an include cycle is reported with the chain of files", "[unit][deck]") {
  // Intent: a.yaml -> b.yaml -> a.yaml stops with a message instead of recursing forever.
  const auto dir = fowtsim::testing::scratch_dir("deck_include_cycle");
  const auto a = write(dir / "a.yaml", "include: b.yaml\nx: 1\n");
  const auto b = write(dir / "b.yaml", "y: 2\ninclude: a.yaml\n");
  const auto error = load_error([&] { load_deck(a); });
  REQUIRE(error.issues.size() == 1);
  CHECK(error.issues[0].kind == DeckIssueKind::include_cycle);
  CHECK_THAT(error.message,
             Catch::Contains(b.string() + ":2:10: include: include cycle " + a.string() + " -> " +
                             b.string() + " -> " + a.string()));
}

TEST_CASE("a key written twice in one mapping is reported", "[unit][deck]") {
  // Intent: YAML parsers silently keep one of two duplicate keys; we refuse both.
  const auto dir = fowtsim::testing::scratch_dir("deck_duplicate");
  const auto file = write(dir / "scene.yaml", "a: 1\nb: 2\na: 3\n");
  const auto error = load_error([&] { load_deck(file); });
  REQUIRE(error.issues.size() == 1);
  CHECK(error.issues[0].kind == DeckIssueKind::duplicate_key);
  CHECK_THAT(error.message,
             Catch::Contains(file.string() + ":3:1: a: duplicate key, first written at " +
                             file.string() + ":1:1"));
}

TEST_CASE("load errors from several files are all reported", "[unit][deck]") {
  // Intent: one run shows every broken include, not only the first.
  const auto dir = fowtsim::testing::scratch_dir("deck_many_load_errors");
  write(dir / "broken.yaml", "a: [1, 2\n");
  const auto scene = write(dir / "scene.yaml", "include: [broken.yaml, gone.yaml]\n");
  const auto error = load_error([&] { load_deck(scene); });
  REQUIRE(error.issues.size() == 2);
  CHECK(error.issues[0].kind == DeckIssueKind::yaml_syntax);
  CHECK(error.issues[1].kind == DeckIssueKind::file_unreadable);
  CHECK_THAT(error.message, Catch::Contains("2 problems"));
}

TEST_CASE("fnv1a_64 matches the published test vectors", "[unit][deck]") {
  // Intent: the hash is standard FNV-1a 64 (vectors from the FNV reference test suite).
  using fowtsim::io::fnv1a_64;
  CHECK(fnv1a_64("") == 0xcbf29ce484222325ULL);
  CHECK(fnv1a_64("a") == 0xaf63dc4c8601ec8cULL);
  CHECK(fnv1a_64("foobar") == 0x85944171f73967e8ULL);
  CHECK(fnv1a_64("bar", fnv1a_64("foo")) == fnv1a_64("foobar"));  // chaining = concatenation
}

TEST_CASE("the deck hash covers included files and changes when one changes", "[unit][deck]") {
  // Intent: a run's recorded hash identifies every input byte, includes included.
  const auto dir = fowtsim::testing::scratch_dir("deck_hash");
  const auto scene = write(dir / "scene.yaml", "include: turbine.yaml\nblades: 3\n");
  write(dir / "turbine.yaml", "radius_m: 63\n");
  const auto before = load_deck(scene);
  CHECK(before.hash.size() == 16);
  CHECK(before.hash == fowtsim::io::deck_hash(before.files));
  CHECK(before.hash == load_deck(scene).hash);  // deterministic

  write(dir / "turbine.yaml", "radius_m: 64\n");
  CHECK(load_deck(scene).hash != before.hash);
}

TEST_CASE("a deck whose YAML aliases expand without bound stops with a clear error", "[unit][io]") {
  // Ten aliases of ten aliases … eleven deep: 10^12 values from a few hundred bytes.
  const auto dir = std::filesystem::temp_directory_path() / "fowtsim_alias_bomb";
  std::filesystem::create_directories(dir);
  {
    std::ofstream f(dir / "bomb.yaml");
    f << "a0: &a0 [1,1,1,1,1,1,1,1,1,1]\n";
    for (int i = 1; i < 12; ++i) {
      f << "a" << i << ": &a" << i << " [";
      for (int k = 0; k < 10; ++k) f << (k ? "," : "") << "*a" << i - 1;
      f << "]\n";
    }
  }
  try {
    fowtsim::io::load_deck(dir / "bomb.yaml");
    FAIL("no error for an alias bomb");
  } catch (const DeckError& e) {
    CHECK_THAT(e.what(), Catch::Contains("nested YAML aliases"));
  }
}
