// Deck schemas: building (with the unit rule), validation errors, and typed reads of a
// validated deck.
#include <catch2/catch.hpp>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fowtsim/io/schema.hpp"
#include "fowtsim/testing/skip.hpp"

namespace {

using fowtsim::io::DeckError;
using fowtsim::io::DeckIssue;
using fowtsim::io::DeckIssueKind;
using fowtsim::io::read_deck;
using fowtsim::io::Schema;
namespace fs = std::filesystem;

// A small scene schema using every kind of field.
Schema scene_schema() {
  return Schema::map({
      {"simulation",
       Schema::map({
           {"t_max_s", Schema::number().unit("s").greater_than(0.0).doc("simulated time")},
           {"dt_coupling_s", Schema::number().unit("s").greater_than(0.0).at_most(1.0)},
           {"substeps", Schema::integer().at_least(1).default_value(10)},
           {"coupling", Schema::choice({"multi_rate", "single_rate", "predictor_corrector"})
                            .default_value("multi_rate")},
           {"seed", Schema::integer().at_least(0).optional()},
           {"write_summary", Schema::boolean().default_value(true)},
       })},
      {"rotor",
       Schema::map({
                       {"rotor_speed_rpm", Schema::number().unit("rpm").at_least(0.0)},
                       {"blade_pitch_deg", Schema::number().unit("deg").default_value(0.0)},
                   })
           .optional()},
      {"output", Schema::map({
                                 {"format", Schema::choice({"hdf5", "text"}).default_value("hdf5")},
                             })
                     .optional()},
      {"mooring_lines",
       Schema::sequence(Schema::map({
                            {"length_m", Schema::number().unit("m").greater_than(0.0)},
                            {"anchor_depth_m", Schema::number().unit("m").default_value(320)},
                        }))
           .optional()},
      {"channels", Schema::sequence(Schema::string()).optional()},
      {"tower_heights_m", Schema::sequence(Schema::number().unit("m")).min_items(2).optional()},
      {"initial_offsets_m", Schema::map_of(Schema::number().unit("m")).optional()},
  });
}

// Writes `text` to `file`, dropping the newline right after R"( so that the first line of the
// literal is line 1 of the file.
fs::path write(const fs::path& file, std::string text) {
  if (!text.empty() && text.front() == '\n') text.erase(0, 1);
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

struct Failure {
  std::string file;               // the deck file written
  std::string message;            // DeckError::what()
  std::vector<DeckIssue> issues;  // DeckError::issues()
};

// Validates `yaml` against scene_schema(); it must fail.
Failure deck_error(const std::string& test_name, const std::string& yaml) {
  const auto file = write(fowtsim::testing::scratch_dir(test_name) / "scene.yaml", yaml);
  try {
    read_deck(scene_schema(), file);
  } catch (const DeckError& error) {
    return {file.string(), error.what(), error.issues()};
  }
  FAIL("no DeckError thrown");
  return {};
}

constexpr const char* valid_deck = R"(
simulation:
  t_max_s: 600
  dt_coupling_s: 0.025
  seed: 42
rotor:
  rotor_speed_rpm: 12.1
output:
mooring_lines:
  - length_m: 902.2
  - length_m: 902.2
    anchor_depth_m: 300
channels: [RotSpeed, GenPwr]
tower_heights_m: [0, 43.8, 87.6]
initial_offsets_m: {surge: 1.5, heave: -0.2}
)";

}  // namespace

TEST_CASE("a valid deck reads back its values with defaults filled in", "[unit][schema]") {
  // Intent: every typed reader returns what the deck says, or the schema default.
  const auto file = write(fowtsim::testing::scratch_dir("schema_valid") / "scene.yaml", valid_deck);
  const auto deck = read_deck(scene_schema(), file);
  CHECK(deck.number("simulation.t_max_s") == 600.0);
  CHECK(deck.number("simulation.dt_coupling_s") == 0.025);
  CHECK(deck.integer("simulation.seed") == 42);
  CHECK(deck.integer("simulation.substeps") == 10);           // default
  CHECK(deck.string("simulation.coupling") == "multi_rate");  // default of a choice
  CHECK(deck.boolean("simulation.write_summary"));            // default
  CHECK(deck.number("rotor.blade_pitch_deg") == 0.0);         // default
  CHECK(deck.string("output.format") == "hdf5");              // `output:` = all defaults
  CHECK(deck.size("mooring_lines") == 2);
  CHECK(deck.number("mooring_lines[0].anchor_depth_m") == 320.0);
  CHECK(deck.number("mooring_lines[1].anchor_depth_m") == 300.0);
  CHECK(deck.strings("channels") == std::vector<std::string>{"RotSpeed", "GenPwr"});
  CHECK(deck.numbers("tower_heights_m") == std::vector<double>{0.0, 43.8, 87.6});
  CHECK(deck.keys("initial_offsets_m") == std::vector<std::string>{"surge", "heave"});
  CHECK(deck.number("initial_offsets_m.heave") == -0.2);
  CHECK(deck.files() == std::vector<fs::path>{file});
  CHECK(deck.hash().size() == 16);
}

TEST_CASE("locations point at the value, or for a default at its mapping", "[unit][schema]") {
  // Intent: later checks by modules can name file:line:col of any value, defaults included.
  const auto file =
      write(fowtsim::testing::scratch_dir("schema_locations") / "scene.yaml", valid_deck);
  const auto deck = read_deck(scene_schema(), file);
  CHECK(deck.location("simulation.t_max_s").to_string() == file.string() + ":2:12");
  CHECK(deck.location("simulation.substeps").to_string() == file.string() + ":2:3");
  CHECK(deck.location("mooring_lines[1].anchor_depth_m").line == 11);
}

TEST_CASE("a section reads its part of the deck with short paths", "[unit][schema]") {
  // Intent: a module is handed its own section and never sees the scene around it.
  const auto file =
      write(fowtsim::testing::scratch_dir("schema_section") / "scene.yaml", valid_deck);
  const auto line = read_deck(scene_schema(), file).section("mooring_lines[1]");
  CHECK(line.path() == "mooring_lines[1]");
  CHECK(line.number("length_m") == 902.2);
  CHECK(line.location("anchor_depth_m").line == 11);
}

TEST_CASE("optional keys left out are absent, and reading them is a programming error",
          "[unit][schema]") {
  // Intent: "no section, no computation" needs has(); reading without it must not invent data.
  const auto file = write(fowtsim::testing::scratch_dir("schema_optional") / "scene.yaml",
                          "simulation: {t_max_s: 1, dt_coupling_s: 0.1}\n");
  const auto deck = read_deck(scene_schema(), file);
  CHECK_FALSE(deck.has("rotor"));
  CHECK_FALSE(deck.has("rotor.rotor_speed_rpm"));
  CHECK_FALSE(deck.has("simulation.seed"));
  CHECK_THROWS_AS(deck.number("rotor.rotor_speed_rpm"), std::logic_error);
  CHECK_THROWS_AS(deck.section("rotor"), std::logic_error);
}

TEST_CASE("reading an undeclared key or with the wrong type is a programming error",
          "[unit][schema]") {
  // Intent: a typo in C++ reading code fails loudly, naming the path and both types.
  const auto file =
      write(fowtsim::testing::scratch_dir("schema_misread") / "scene.yaml", valid_deck);
  const auto deck = read_deck(scene_schema(), file);
  CHECK_THROWS_WITH(deck.number("simulation.t_max"),
                    Catch::Contains("`simulation.t_max`") && Catch::Contains("not declared"));
  CHECK_THROWS_WITH(deck.integer("simulation.t_max_s"),
                    Catch::Contains("declared as number > 0 [s] but read with integer()"));
  CHECK_THROWS_AS(deck.strings("tower_heights_m"), std::logic_error);
  CHECK_THROWS_AS(deck.number("channels[0]"), std::logic_error);
}

TEST_CASE("an unknown key names its path and location and suggests the near key",
          "[unit][schema]") {
  // Intent: a typo (here a forgotten unit suffix) is caught with a fix-it hint.
  const auto error = deck_error("schema_unknown_key", R"(
simulation:
  t_max_s: 600
  dt_coupling: 0.025
)");
  CHECK(error.issues[0].kind == DeckIssueKind::unknown_key);
  CHECK_THAT(error.message,
             Catch::Contains(error.file + ":3:3: simulation.dt_coupling: unknown key"));
  CHECK_THAT(error.message, Catch::Contains("did you mean `dt_coupling_s`?"));
  CHECK_THAT(error.message, Catch::Contains("t_max_s, dt_coupling_s, substeps"));
}

TEST_CASE("a missing required key is reported at the mapping that lacks it", "[unit][schema]") {
  // Intent: the user learns where to add the key and what it must hold.
  const auto error = deck_error("schema_missing_key", R"(
simulation:
  t_max_s: 600
)");
  REQUIRE(error.issues.size() == 1);
  CHECK(error.issues[0].kind == DeckIssueKind::missing_key);
  CHECK_THAT(error.message,
             Catch::Contains(error.file + ":2:3: simulation.dt_coupling_s: missing required key; "
                                          "expected a number > 0 and <= 1 [s]"));
}

TEST_CASE("values of the wrong type are reported with what was expected", "[unit][schema]") {
  // Intent: text for a number, a mapping for a scalar, a fraction for an integer, a YAML 1.1
  // boolean, and a unit written into the value are each named.
  const auto error = deck_error("schema_wrong_type", R"(
simulation:
  t_max_s: ten
  dt_coupling_s: {value: 0.1}
  substeps: 2.5
  write_summary: yes
rotor:
  rotor_speed_rpm: 12.1 rpm
)");
  REQUIRE(error.issues.size() == 5);
  for (const auto& issue : error.issues) CHECK(issue.kind == DeckIssueKind::wrong_type);
  const std::string& m = error.message;
  CHECK_THAT(m, Catch::Contains(":2:12: simulation.t_max_s: expected a number > 0 [s], found ten"));
  CHECK_THAT(m, Catch::Contains(":3:18: simulation.dt_coupling_s: expected a number > 0 and <= 1 "
                                "[s], found a mapping"));
  CHECK_THAT(m, Catch::Contains("simulation.substeps: expected an integer >= 1, found 2.5"));
  CHECK_THAT(m, Catch::Contains("simulation.write_summary: expected true or false, found yes"));
  CHECK_THAT(m, Catch::Contains("rotor.rotor_speed_rpm: expected a number >= 0 [rpm], found 12.1 "
                                "rpm; write the plain number 12.1: the key name says the unit"));
}

TEST_CASE("out-of-range values name the key, the range and the unit", "[unit][schema]") {
  // Intent: bounds (exclusive and inclusive) and sequence lengths are checked.
  const auto error = deck_error("schema_range", R"(
simulation:
  t_max_s: 0
  dt_coupling_s: -0.1
tower_heights_m: [0]
)");
  REQUIRE(error.issues.size() == 3);
  for (const auto& issue : error.issues) CHECK(issue.kind == DeckIssueKind::out_of_range);
  CHECK_THAT(error.message, Catch::Contains(error.file + ":2:12: simulation.t_max_s: expected a "
                                                         "number > 0 [s], found 0"));
  CHECK_THAT(error.message,
             Catch::Contains(error.file + ":3:18: simulation.dt_coupling_s: "
                                          "expected a number > 0 and <= 1 [s], found -0.1"));
  CHECK_THAT(error.message, Catch::Contains("tower_heights_m: expected a sequence (at least 2 "
                                            "items) of number [m], found 1 item"));
}

TEST_CASE("a value outside a choice lists the allowed values and suggests one", "[unit][schema]") {
  // Intent: enumerations say what they accept.
  const auto error = deck_error("schema_choice", R"(
simulation:
  t_max_s: 600
  dt_coupling_s: 0.025
  coupling: multirate
)");
  REQUIRE(error.issues.size() == 1);
  CHECK(error.issues[0].kind == DeckIssueKind::not_in_choices);
  CHECK_THAT(error.message,
             Catch::Contains(error.file +
                             ":4:13: simulation.coupling: expected one of multi_rate, "
                             "single_rate, predictor_corrector, found multirate; did you mean "
                             "`multi_rate`?"));
}

TEST_CASE("every problem of a deck, in the scene and its includes, is reported at once",
          "[unit][schema]") {
  // Intent: one run shows all mistakes; included values are located in the included file.
  const auto dir = fowtsim::testing::scratch_dir("schema_many");
  const auto rotor = write(dir / "rotor.yaml", "rotor_speed_rpm: -1\nblade_pitch: 0\n");
  const auto scene = write(dir / "scene.yaml", R"(
simulation:
  t_max_s: -600
  coupling: weak
  substeps: many
rotor:
  include: rotor.yaml
outputs: {}
)");
  try {
    read_deck(scene_schema(), scene);
    FAIL("no DeckError thrown");
  } catch (const DeckError& error) {
    CHECK(error.issues().size() == 7);
    const std::string message = error.what();
    CHECK_THAT(message, Catch::StartsWith("io.deck: 7 problems in the input deck:\n"));
    CHECK_THAT(message, Catch::Contains(scene.string() + ":2:12: simulation.t_max_s"));
    CHECK_THAT(message, Catch::Contains(scene.string() + ":3:13: simulation.coupling"));
    CHECK_THAT(message, Catch::Contains(scene.string() + ":4:13: simulation.substeps"));
    CHECK_THAT(message,
               Catch::Contains(scene.string() + ":2:3: simulation.dt_coupling_s: missing"));
    CHECK_THAT(message, Catch::Contains(rotor.string() + ":1:18: rotor.rotor_speed_rpm"));
    CHECK_THAT(message, Catch::Contains(rotor.string() + ":2:1: rotor.blade_pitch: unknown key"));
    CHECK_THAT(message, Catch::Contains("did you mean `blade_pitch_deg`?"));
    CHECK_THAT(message, Catch::Contains(scene.string() + ":7:1: outputs: unknown key"));
  }
}

TEST_CASE("the unit rule: a number with a unit must sit under a key ending in that unit",
          "[unit][schema]") {
  // Intent: one rule for every deck key in the project, enforced when the schema is built.
  CHECK_THROWS_WITH(Schema::map({{"t_max", Schema::number().unit("s")}}),
                    Catch::Contains("`t_max`") && Catch::Contains("`_s`"));
  CHECK_THROWS_AS(Schema::map({{"rotor_speed", Schema::number().unit("rpm")}}), std::logic_error);
  CHECK_THROWS_AS(Schema::map({{"heights", Schema::sequence(Schema::number().unit("m"))}}),
                  std::logic_error);
  CHECK_NOTHROW(Schema::map({{"t_max_s", Schema::number().unit("s")},
                             {"stiffness_N_m", Schema::number().unit("N_m")},
                             {"heights_m", Schema::sequence(Schema::number().unit("m"))},
                             {"blade_count", Schema::integer()}}));
}

TEST_CASE("schema misuse is a programming error", "[unit][schema]") {
  // Intent: defaults must satisfy their own field, modifiers must fit the type.
  CHECK_THROWS_AS(Schema::map({{"substeps", Schema::integer().at_least(1).default_value(0)}}),
                  std::logic_error);
  CHECK_THROWS_AS(Schema::map({{"mode", Schema::choice({"a", "b"}).default_value("c")}}),
                  std::logic_error);
  CHECK_THROWS_AS(Schema::integer().default_value(1.5), std::logic_error);
  CHECK_THROWS_AS(Schema::string().at_least(0.0), std::logic_error);
  CHECK_THROWS_AS(Schema::string().unit("m"), std::logic_error);
  CHECK_THROWS_AS(Schema::map({{"a", Schema::number()}, {"a", Schema::number()}}),
                  std::logic_error);
  CHECK_THROWS_AS(Schema::map({{"include", Schema::string()}}), std::logic_error);
}

TEST_CASE("describe_schema documents every key with type, range, unit, default and doc",
          "[unit][schema]") {
  // Intent: the text behind `fowtsim --help-deck` is complete.
  const std::string text = fowtsim::io::describe_schema(scene_schema());
  CHECK_THAT(text, Catch::Contains("simulation: mapping, required\n"));
  CHECK_THAT(text,
             Catch::Contains("simulation.t_max_s: number > 0 [s], required\n    simulated time\n"));
  CHECK_THAT(text, Catch::Contains("simulation.substeps: integer >= 1, default 10\n"));
  CHECK_THAT(text, Catch::Contains("simulation.coupling: one of multi_rate, single_rate, "
                                   "predictor_corrector, default multi_rate\n"));
  CHECK_THAT(text, Catch::Contains("mooring_lines[].length_m: number > 0 [m], required\n"));
  CHECK_THAT(text,
             Catch::Contains("initial_offsets_m: mapping of names to number [m], optional\n"));
}
