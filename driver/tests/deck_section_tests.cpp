// One declaration per deck key (decks/deck_section.hpp): the schema and the reader come from the
// same list, so every key the schema accepts lands in its field.
#include <fstream>

#include <catch2/catch.hpp>

#include "decks/controller_deck.hpp"
#include "decks/deck_section.hpp"
#include "decks/mooring_deck.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/io/deck.hpp"
#include "fowtsim/testing/skip.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;
using io::Schema;

namespace {

struct Inner {
  int count = 7;
};
struct Outer {
  double length_m = -1.0;
  bool on = false;
  std::string name = "unset";
  Vec3 point_m = Vec3::Zero();
  Inner inner;
  std::vector<Inner> items;
};

DeckSection<Outer> outer_section() {
  DeckSection<Inner> inner;
  inner.key("count", Schema::integer().at_least(0).default_value(3).doc("a count"), &Inner::count);
  DeckSection<Outer> outer;
  outer.key("length_m", Schema::number().greater_than(0.0).doc("a length"), &Outer::length_m)
      .key("on", Schema::boolean().default_value(true).doc("a switch"), &Outer::on)
      .key("name", Schema::string().optional().doc("a name"), &Outer::name)
      .key("point_m", number_vector(3, "a point"), &Outer::point_m)
      .section("inner", inner, &Outer::inner, true, "an optional mapping")
      .list("items", inner, &Outer::items, 0, "a list");
  return outer;
}

Outer read(const std::string& yaml) {
  const auto dir = testing::scratch_dir("deck_section");
  std::ofstream(dir / "deck.yaml") << yaml;
  const DeckSection<Outer> section = outer_section();
  const io::ValidatedDeck deck = io::read_deck(Schema::map({{"outer", section.schema()}}), dir / "deck.yaml");
  Outer o;
  section.read_into(deck.section("outer"), o);
  return o;
}

}  // namespace

TEST_CASE("a deck section reads every declared key into its field, defaults included", "[unit][decks]") {
  const Outer o = read("outer: {length_m: 2.5, point_m: [1, 2, 3], items: [{count: 4}, {}]}\n");
  CHECK(o.length_m == 2.5);
  CHECK(o.on);                 // default
  CHECK(o.name == "unset");    // optional key left out: the field keeps its value
  CHECK(o.point_m == Vec3(1, 2, 3));
  CHECK(o.inner.count == 7);   // optional mapping left out: the struct's own default
  REQUIRE(o.items.size() == 2);
  CHECK(o.items[0].count == 4);
  CHECK(o.items[1].count == 3);  // the schema's default
  const Outer given = read("outer: {length_m: 1, on: false, name: x, point_m: [0, 0, 0], inner: {count: 9}, items: []}\n");
  CHECK_FALSE(given.on);
  CHECK(given.name == "x");
  CHECK(given.inner.count == 9);
}

TEST_CASE("a deck key bound to a field of another type is refused when the section is built", "[unit][decks]") {
  DeckSection<Outer> s;
  CHECK_THROWS_AS(s.key("length_m", Schema::integer(), &Outer::length_m), std::logic_error);
  CHECK_THROWS_AS(s.key("on", Schema::number(), &Outer::on), std::logic_error);
}

TEST_CASE("the mooring section's schema and reader agree with the OC3 deck", "[unit][decks]") {
  const io::ValidatedDeck deck =
      io::read_deck(Schema::map({{"mooring", mooring_schema()}}), testing::source_dir() / "inputs/oc3_hywind/mooring.yaml");
  const mooring::MooringParams p = mooring_params(deck.section("mooring"));
  // OC3-Hywind (Jonkman 2010, Table 5-1): 320 m depth, three lines of 902.2 m, EA 384.243 MN.
  CHECK(p.depth_m == 320.0);
  REQUIRE(p.lines.size() == 3);
  CHECK(p.lines[0].unstretched_length_m == 902.2);
  CHECK(p.lines[2].ea_N == 384243000.0);
  CHECK(p.solver.max_bisection_iterations == 200);  // the schema's default, as the module's
}

TEST_CASE("the controller section fills the baseline law, and a DISCON library relative to its deck", "[unit][decks]") {
  const auto dir = testing::scratch_dir("deck_section_controller");
  auto section = [&](const std::string& yaml) {
    std::ofstream(dir / "deck.yaml") << yaml;
    return io::read_deck(Schema::map({{"controller", controller_schema()}}), dir / "deck.yaml").section("controller");
  };
  // One key, both laws' fields: the pitch limit lands in the baseline parameters here.
  const ControllerParams baseline = controller_params(section("controller: {max_pitch_rad: 1.2, integral_gain: 0.01}\n"));
  REQUIRE(std::holds_alternative<control::BaselineParams>(baseline));
  CHECK(std::get<control::BaselineParams>(baseline).max_pitch_rad == 1.2);
  CHECK(std::get<control::BaselineParams>(baseline).integral_gain == 0.01);
  CHECK(std::get<control::BaselineParams>(baseline).rated_power_W == control::BaselineParams{}.rated_power_W);  // default
  const std::string missing = [&] {
    try {
      controller_params(section("controller: {type: discon, library: libnothere.so}\n"));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  }();
  CHECK_THAT(missing, Catch::Contains((dir / "libnothere.so").lexically_normal().string()));  // resolved beside the deck
  CHECK_THROWS_WITH(controller_params(section("controller: {type: discon}\n")), Catch::Contains("type discon needs `library`"));
}

TEST_CASE("the controller section chooses ServoDyn's simple modes; their keys come with their law", "[unit][decks]") {
  const auto dir = testing::scratch_dir("deck_section_simple_modes");
  auto params = [&](const std::string& yaml) {
    std::ofstream(dir / "deck.yaml") << yaml;
    return controller_params(io::read_deck(Schema::map({{"controller", controller_schema()}}), dir / "deck.yaml").section("controller"));
  };
  // The shipped deck: both laws swapped, the four simple-VS inputs in SI, no PI gains needed.
  const ControllerParams shipped = params("include: [" + (testing::source_dir() / "inputs/nrel5mw/controller_simple_vs.yaml").string() +
                                          "]\ncontroller: {integral_gain: 0.0}\n");
  REQUIRE(std::holds_alternative<control::BaselineParams>(shipped));
  const auto& p = std::get<control::BaselineParams>(shipped);
  CHECK(p.generator == control::GeneratorLaw::simple_vs);
  CHECK(p.pitch == control::PitchLaw::fixed);
  CHECK(p.simple_vs.rated_generator_speed_rad_s == 122.90958);
  CHECK(p.simple_vs.rated_torque_N_m == 43093.55);
  CHECK(p.simple_vs.region2_gain_N_m_s2 == 2.332288);
  CHECK(p.simple_vs.slip_percent == 10.0);
  // Defaults: the baseline laws.
  const auto d = std::get<control::BaselineParams>(params("controller: {}\n"));
  CHECK(d.generator == control::GeneratorLaw::baseline);
  CHECK(d.pitch == control::PitchLaw::baseline);
  // A law without its keys, keys without their law, a missing key, and the simple modes on a DISCON.
  CHECK_THROWS_WITH(params("controller: {generator: simple_vs}\n"), Catch::Contains("needs the `simple_vs` section"));
  const std::string keys = "simple_vs: {rated_generator_speed_rad_s: 122.9, rated_torque_N_m: 43093.55, region2_gain_N_m_s2: 2.33, slip_percent: 10}";
  CHECK_THROWS_WITH(params("controller: {" + keys + "}\n"), Catch::Contains("given but generator is baseline"));
  CHECK_THROWS_WITH(params("controller: {generator: simple_vs, simple_vs: {rated_torque_N_m: 1.0}}\n"),
                    Catch::Contains("rated_generator_speed_rad_s"));
  CHECK_THROWS_WITH(params("controller: {type: discon, library: x.so, pitch: fixed}\n"), Catch::Contains("built-in controller only"));
  CHECK_NOTHROW(params("controller: {pitch: fixed, integral_gain: 0.0}\n"));  // PCMode 0 with the baseline torque
}
