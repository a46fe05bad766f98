// The command line's --set key.path=value over a loaded deck (apply_settings): values as YAML,
// merged as a sweep's case deck merges, errors naming the setting and the key, and a deck hash
// that tells the settings apart.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/deck.hpp"
#include "fowtsim/io/schema.hpp"
#include "fowtsim/testing/exception_message.hpp"
#include "fowtsim/testing/skip.hpp"

namespace {

using fowtsim::io::DeckError;
using fowtsim::io::Schema;
namespace fs = std::filesystem;

fs::path deck_file(const std::string& name) {
  const fs::path dir = fowtsim::testing::scratch_dir("deck_settings");
  std::ofstream(dir / "base.yaml") << "wind:\n  speed_m_s: 12\n  model: steady\n";
  std::ofstream(dir / name) << "include: base.yaml\nsimulation:\n  t_max_s: 600\n";
  return dir / name;
}

Schema scene_schema() {
  return Schema::map({
      {"simulation", Schema::map({{"t_max_s", Schema::number().unit("s").greater_than(0.0)},
                                  {"dt_s", Schema::number().unit("s").default_value(0.05)}})},
      {"wind", Schema::map({{"speed_m_s", Schema::number().unit("m_s")},
                            {"model", Schema::choice({"steady", "turbulent"})},
                            {"turbulence", Schema::map({{"seed", Schema::integer()}}).optional()}})},
      {"output", Schema::map({{"channels", Schema::sequence(Schema::string())}}).optional()},
  });
}

using fowtsim::testing::message_of;

}  // namespace

TEST_CASE("settings (--set) set keys over the deck and its includes, as YAML values", "[unit][deck]") {
  const fs::path file = deck_file("scene.yaml");
  const auto deck = fowtsim::io::read_deck(
      scene_schema(), file,
      {"wind.speed_m_s=14.5", "simulation.t_max_s=60", "wind.turbulence.seed=7", "output.channels=[RotSpeed, GenPwr]",
       "wind.model=turbulent"});
  CHECK(deck.number("wind.speed_m_s") == 14.5);      // over an included key
  CHECK(deck.number("simulation.t_max_s") == 60.0);  // over the deck's own key
  CHECK(deck.integer("wind.turbulence.seed") == 7);  // a mapping made on the way
  CHECK(deck.strings("output.channels") == std::vector<std::string>{"RotSpeed", "GenPwr"});
  CHECK(deck.string("wind.model") == "turbulent");
  CHECK(deck.number("simulation.dt_s") == 0.05);  // the rest of the mapping is kept
  CHECK(deck.location("wind.speed_m_s").file == "--set wind.speed_m_s");
  CHECK(deck.location("simulation").file == file.string());  // a mapping on the way keeps its place
  // A later setting of the same key wins.
  CHECK(fowtsim::io::read_deck(scene_schema(), file, {"wind.speed_m_s=3", "wind.speed_m_s=4"}).number("wind.speed_m_s") == 4.0);
}

TEST_CASE("settings (--set) change the deck hash, by the settings and their order", "[unit][deck]") {
  const fs::path file = deck_file("hashed.yaml");
  const std::string plain = fowtsim::io::read_deck(scene_schema(), file).hash();
  const std::string set14 = fowtsim::io::read_deck(scene_schema(), file, {"wind.speed_m_s=14"}).hash();
  const std::string set15 = fowtsim::io::read_deck(scene_schema(), file, {"wind.speed_m_s=15"}).hash();
  CHECK(plain == fowtsim::io::load_deck(file).hash);
  CHECK(set14 != plain);
  CHECK(set14 != set15);
  CHECK(set14 == fowtsim::io::read_deck(scene_schema(), file, {"wind.speed_m_s=14"}).hash());
  CHECK(fowtsim::io::read_deck(scene_schema(), file, {"wind.speed_m_s=1", "wind.speed_m_s=2"}).hash() !=
        fowtsim::io::read_deck(scene_schema(), file, {"wind.speed_m_s=2", "wind.speed_m_s=1"}).hash());
}

TEST_CASE("settings (--set): errors name the setting and the key, with the schema's did-you-mean", "[unit][deck]") {
  const fs::path file = deck_file("wrong.yaml");
  auto read = [&](std::vector<std::string> settings) { fowtsim::io::read_deck(scene_schema(), file, settings); };
  CHECK_THAT(message_of([&] { read({"wind.speed=14"}); }),
             Catch::Contains("--set wind.speed: wind.speed: unknown key") && Catch::Contains("did you mean `speed_m_s`?"));
  CHECK_THAT(message_of([&] { read({"wind.speed_m_s=fast"}); }),
             Catch::Contains("--set wind.speed_m_s: wind.speed_m_s: expected a number") && Catch::Contains("found fast"));
  CHECK_THAT(message_of([&] { read({"simulation.t_max_s=-1"}); }), Catch::Contains("--set simulation.t_max_s: simulation.t_max_s"));
  CHECK_THROWS_AS(read({"wind.speed_m_s=[1, 2"}), DeckError);  // not YAML
  CHECK_THAT(message_of([&] { read({"wind.speed_m_s"}); }), Catch::Contains("--set wind.speed_m_s: expected key.path=value"));
  CHECK_THAT(message_of([&] { read({"output.channels[0]=X"}); }), Catch::Contains("a sequence is set whole"));
  CHECK_THAT(message_of([&] { read({"wind..speed_m_s=1"}); }), Catch::Contains("not a key path"));
  CHECK_THAT(message_of([&] { read({"include=other.yaml"}); }), Catch::Contains("`include` cannot be set"));
}
