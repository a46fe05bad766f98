// Sweep specs (issue 14): expansion counts, names, seeds and the deck each case gets, for every
// preset and for crossed and zipped specs; bad specs stop with file:line errors.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <numbers>
#include <set>

#include <fmt/format.h>

#include "fowtsim/io/deck.hpp"
#include "fowtsim/wind/iec_conditions.hpp"
#include "fowtsim/testing/skip.hpp"
#include "sweep/case_expansion.hpp"
#include "sweep/case_files.hpp"
#include "sweep/iec_presets.hpp"
#include "sweep/sweep_spec.hpp"

using namespace fowtsim;
using namespace fowtsim::driver::sweep;

namespace {

const std::filesystem::path kBaseDeck = testing::source_dir() / "inputs/oc3_hywind/turbine_ntm_12mps_irregular.yaml";

// Writes a spec whose sweep section names the rigid OC3 deck, followed by `body`.
std::filesystem::path write_spec(const std::string& test, const std::string& body, const std::string& sweep_name = "") {
  const std::filesystem::path dir = testing::scratch_dir(test);
  const std::filesystem::path path = dir / "spec.yaml";
  std::ofstream(path) << "sweep:\n  name: " << (sweep_name.empty() ? test : sweep_name) << "\n  base_deck: " << kBaseDeck.string() << "\n  output_dir: "
                      << (dir / "out").string() << "\n" << body;
  return path;
}

std::vector<SweepCase> expand(const std::filesystem::path& spec_path) {
  const SweepSpec spec = read_sweep_spec(spec_path);
  return expand_cases(spec, read_base_deck_facts(spec.base_deck));
}

std::string override_of(const SweepCase& c, const std::string& key) {
  std::string value;
  for (const DeckOverride& o : c.overrides)
    if (o.key_path == key) value = o.yaml_value;  // the last one applies
  return value;
}

std::string error_of(const std::filesystem::path& spec_path) {
  try {
    const SweepSpec spec = read_sweep_spec(spec_path);
    write_case_decks(spec, expand_cases(spec, read_base_deck_facts(spec.base_deck)), SweepLayout{spec.output_dir});
  } catch (const io::DeckError& e) {
    return e.what();
  }
  FAIL("expected a DeckError");
  return "";
}

}  // namespace

TEST_CASE("sweep presets: DLC 1.2 expands speeds × six NTM seeds with the normal sea of the table", "[unit][sweep]") {
  const auto cases = expand(write_spec("preset_dlc12", R"(load_cases:
  - name: dlc12
    preset: dlc1.2
    wind_speeds_m_s: [6, 12]
    sea_state:
      table:
        - {wind_speed_m_s: 4, hs_m: 1.0, tp_s: 6.0}
        - {wind_speed_m_s: 24, hs_m: 5.0, tp_s: 11.0}
)"));
  REQUIRE(cases.size() == 2 * kPresetSeeds);
  CHECK(cases[0].name == "dlc12_ws6_s1");
  CHECK(cases[11].name == "dlc12_ws12_s6");
  CHECK(cases[0].fatigue);  // DLC 1.2 is the fatigue case
  // Hs, Tp interpolated linearly at 12 m/s: 1 + 8/20·4 = 2.6 m, 6 + 8/20·5 = 8 s.
  CHECK(cases[6].hs_m.value() == Approx(2.6).epsilon(1e-12));
  CHECK(cases[6].tp_s.value() == Approx(8.0).epsilon(1e-12));
  CHECK(override_of(cases[6], "wind.model") == "turbulent");
  CHECK(override_of(cases[6], "wind.turbulence.model") == "NTM");
  CHECK(override_of(cases[6], "wind.turbulence.class") == "B");
  CHECK(override_of(cases[6], "wind.speed_m_s") == "12");
  CHECK(override_of(cases[6], "simulation.t_max_s") == "720");  // 120 s transient + 600 s analysed by default
  CHECK(override_of(cases[6], "waves.duration_s") == "720");
  // The box outlasts the run by the time it needs to pass the rotor: ⌈145 m / 12 m/s⌉ = 13 s.
  CHECK(override_of(cases[6], "wind.turbulence.duration_s") == "733");
  // Every realisation has its own wind and wave seeds, written into its deck.
  std::set<std::uint64_t> seeds;
  for (const SweepCase& c : cases) {
    seeds.insert(c.wind_seed.value());
    seeds.insert(c.wave_seed.value());
    CHECK(override_of(c, "wind.turbulence.seed") == std::to_string(*c.wind_seed));
    CHECK(override_of(c, "waves.seed") == std::to_string(*c.wave_seed));
  }
  CHECK(seeds.size() == 2 * cases.size());
  // NTM σ1 = I_ref (0.75 V + 5.6) with I_ref = 0.14 (class B): 2.044 m/s at 12 m/s (IEC 61400-1 ed.3 eq. 11).
  CHECK(wind::ntm_sigma(wind::TurbulenceCategory::B, 12.0) == Approx(2.044).epsilon(1e-12));
}

TEST_CASE("sweep presets: DLC 1.1 and 1.6 are NTM cases, 1.6 with the severe sea, neither in the fatigue sum", "[unit][sweep]") {
  const auto cases = expand(write_spec("preset_dlc11_16", R"(turbine: {wind_class: 2, turbulence_class: A, hub_height_m: 90}
load_cases:
  - name: dlc11
    preset: dlc1.1
    wind_speeds_m_s: [10]
    seeds: 1
    sea_state: {relation: {hs_coefficients: [0.8, 0.1], tp_factor: 12.7}}
  - name: dlc16
    preset: dlc1.6
    wind_speeds_m_s: [10, 20]
    seeds: 2
    sea_state: {hs_m: 9.5, tp_s: 13.0}
)"));
  REQUIRE(cases.size() == 1 + 2 * 2);
  CHECK(cases[0].name == "dlc11_ws10");  // one seed: no _s suffix
  // The normal-sea relation of the spec: Hs = 0.8 + 0.1·10 = 1.8 m, Tp = 12.7 √(1.8 / 9.80665).
  CHECK(cases[0].hs_m.value() == Approx(1.8).epsilon(1e-12));
  CHECK(cases[0].tp_s.value() == Approx(12.7 * std::sqrt(1.8 / 9.80665)).epsilon(1e-12));
  CHECK(override_of(cases[0], "wind.turbulence.class") == "A");
  CHECK_FALSE(cases[0].fatigue);
  CHECK(cases[1].name == "dlc16_ws10_s1");
  CHECK(cases[4].name == "dlc16_ws20_s2");
  CHECK(override_of(cases[4], "waves.hs_m") == "9.5");
  CHECK(override_of(cases[4], "waves.tp_s") == "13");
  CHECK_FALSE(cases[4].fatigue);
}

TEST_CASE("sweep presets: DLC 6.1 idles the rotor in the turbulent 50-year EWM at yaw −8, 0, +8°", "[unit][sweep]") {
  const auto cases = expand(write_spec("preset_dlc61", R"(turbine: {wind_class: 1}
load_cases:
  - name: dlc61
    preset: dlc6.1
    seeds: 2
    sea_state: {hs_m: 10.9, tp_s: 14.0}
)"));
  REQUIRE(cases.size() == 3 * 2);
  CHECK(cases[0].name == "dlc61_yaw-8_s1");
  CHECK(cases[2].name == "dlc61_yaw0_s1");
  CHECK(cases[5].name == "dlc61_yaw8_s2");
  // The turbulent EWM (IEC 61400-1 ed. 4 §6.3.3.2): 10-minute mean V_50 = V_ref = 50 m/s at hub
  // height for class I, profile exponent 0.11, σ1 = 0.11 V_hub (the generator's EWM model).
  CHECK(cases[0].wind_speed_m_s.value() == 50.0);
  CHECK(override_of(cases[0], "wind.model") == "turbulent");
  CHECK(override_of(cases[0], "wind.turbulence.model") == "EWM");
  CHECK(override_of(cases[0], "wind.shear_exponent") == "0.11");
  CHECK(override_of(cases[0], "wind.direction_deg") == "-8");
  CHECK(cases[0].wind_seed);
  CHECK(cases[0].wave_seed);
  // Idling: rotor free from rest, feathered at the base deck's own upper pitch limit (OC3:
  // 1.570796 rad, 90°), the controller in its idling mode (generator off, pitch held there).
  CHECK(override_of(cases[0], "controller.operating_mode") == "idling");
  CHECK(override_of(cases[0], "structure.initial_conditions.rotor_speed_rpm") == "0");
  CHECK(override_of(cases[0], "structure.initial_conditions.blade_pitch_deg") == fmt::format("{}", 1.570796 * 180.0 / std::numbers::pi));
}

TEST_CASE("sweep specs: crossed factors give every combination, zipped ones pair values index by index", "[unit][sweep]") {
  const std::string factors = R"(
    wind_speeds_m_s: [8, 12]
    yaw_misalignment_deg: [0, 10]
    wave_heading_deg: [0, 30]
    set:
      controller.min_pitch_rad: [0, 0.05]
      wind.turbulence.ny: [9]
    seeds: 2
)";
  const auto crossed = expand(write_spec("crossed", "load_cases:\n  - name: x\n    combine: cross" + factors, "pair"));
  REQUIRE(crossed.size() == 2 * 2 * 2 * 2 * 2);
  // Speed outermost, then yaw, heading, set keys, realisation; constant factors do not name cases.
  CHECK(crossed[0].name == "x_ws8_yaw0_wh0_min_pitch_rad0_s1");
  CHECK(crossed[1].name == "x_ws8_yaw0_wh0_min_pitch_rad0_s2");
  CHECK(crossed[2].name == "x_ws8_yaw0_wh0_min_pitch_rad0.05_s1");
  CHECK(crossed.back().name == "x_ws12_yaw10_wh30_min_pitch_rad0.05_s2");
  CHECK(override_of(crossed.back(), "waves.heading_deg") == "30");
  CHECK(override_of(crossed.back(), "wind.direction_deg") == "10");
  CHECK(override_of(crossed.back(), "wind.turbulence.ny") == "9");

  const auto zipped = expand(write_spec("zipped", "load_cases:\n  - name: x\n    combine: zip" + factors, "pair"));
  REQUIRE(zipped.size() == 2 * 2);
  CHECK(zipped[0].name == "x_ws8_yaw0_wh0_min_pitch_rad0_s1");
  CHECK(zipped[3].name == "x_ws12_yaw10_wh30_min_pitch_rad0.05_s2");
  CHECK(override_of(zipped[3], "controller.min_pitch_rad") == "0.05");
  CHECK(override_of(zipped[3], "wind.turbulence.ny") == "9");  // one value: shared by all

  // The base deck's wind is turbulent and its sea irregular: every case gets both seeds, and a
  // case's seeds depend on the sweep name, group and factors only (the same case in the crossed
  // and the zipped expansion of one sweep gets the same seeds).
  CHECK(zipped[0].wind_seed == crossed[0].wind_seed);
  CHECK(zipped[0].wave_seed == crossed[0].wave_seed);
  CHECK(zipped[0].wind_seed != zipped[1].wind_seed);
}

TEST_CASE("sweep seeds: FNV-1a of the case's factors, the same on every machine and in every run", "[unit][sweep]") {
  // A fixed value: std::hash or an address would change between machines and runs.
  CHECK(case_seed("s|g|wind.speed_m_s=12|realisation=1", "wind") == 157875535u);
  CHECK(case_seed("s|g|wind.speed_m_s=12|realisation=1", "wind") < (1u << 31));
  CHECK(case_seed("s|g|wind.speed_m_s=12|realisation=1", "waves") != case_seed("s|g|wind.speed_m_s=12|realisation=1", "wind"));
  const auto spec = write_spec("stable_seeds", "load_cases:\n  - name: a\n    wind_speeds_m_s: [9]\n    seeds: 3\n");
  const auto first = expand(spec), second = expand(spec);
  for (std::size_t i = 0; i < first.size(); ++i) CHECK(first[i].wind_seed == second[i].wind_seed);
}

TEST_CASE("sweep case decks include the base deck and override only their own keys", "[unit][sweep]") {
  const std::filesystem::path spec_path = write_spec("case_decks", R"(load_cases:
  - name: c
    wind_speeds_m_s: [7.5]
    set: {waves.hs_m: [2.5]}
)");
  const SweepSpec spec = read_sweep_spec(spec_path);
  const auto cases = expand_cases(spec, read_base_deck_facts(spec.base_deck));
  const SweepLayout layout{spec.output_dir};
  const auto hashes = write_case_decks(spec, cases, layout);
  REQUIRE(hashes.size() == 1);
  const io::LoadedDeck deck = io::load_deck(layout.deck("c_ws7.5"));
  CHECK(deck.hash == hashes[0]);
  auto scalar = [&](const char* section, const char* key) { return deck.root.find(section)->find(key)->scalar; };
  // Overridden by the case…
  CHECK(scalar("wind", "speed_m_s") == "7.5");
  CHECK(scalar("waves", "hs_m") == "2.5");
  CHECK(scalar("simulation", "t_max_s") == "720");
  // …and kept from the base deck (inputs/wind/oc3_ntm_12mps.yaml, sea_oc3_deck.yaml, the deck itself).
  CHECK(scalar("wind", "shear_exponent") == "0.2");
  CHECK(deck.root.find("wind")->find("turbulence")->find("ny")->scalar == "31");
  CHECK(scalar("waves", "tp_s") == "10.0");
  CHECK(scalar("simulation", "dt_s") == "0.025");
  // A deck that did not change keeps its hash (resume compares it with the output's deck_hash).
  CHECK(write_case_decks(spec, cases, layout) == hashes);
}

TEST_CASE("bad sweep specs stop with file:line errors, all of them at once", "[unit][sweep]") {
  // Schema problems (types, ranges, unknown keys) are reported together…
  const std::filesystem::path schema = write_spec("bad_schema", R"(load_cases:
  - name: b
    seeds: 0
    turbulence: {}
)");
  const std::string schema_message = error_of(schema);
  CHECK_THAT(schema_message, Catch::Contains(schema.string() + ":7:12: load_cases[0].seeds: expected an integer >= 1, found 0"));
  CHECK_THAT(schema_message, Catch::Contains(schema.string() + ":8:5: load_cases[0].turbulence: unknown key"));

  // …then the spec's own rules, together.
  const std::filesystem::path rules = write_spec("bad_rules", R"(load_cases:
  - name: a
    preset: dlc1.2
    sea_state: {hs_m: 2.0, tp_s: 8.0, relation: {hs_coefficients: [1], tp_factor: 12}}
  - name: b
    combine: zip
    wind_speeds_m_s: [8, 10, 12]
    yaw_misalignment_deg: [0, 5]
)");
  const std::string rules_message = error_of(rules);
  CHECK_THAT(rules_message, Catch::Contains(rules.string() + ":8:16: load_cases[0].sea_state: expected exactly one of hs_m + tp_s, table, relation"));
  CHECK_THAT(rules_message, Catch::Contains(rules.string() + ":6:5: load_cases[0].wind_speeds_m_s: missing required key"));
  CHECK_THAT(rules_message, Catch::Contains(rules.string() + ":12:27: load_cases[1].yaw_misalignment_deg: expected 3 values"));

  // A `set` key the scene does not know is reported at its line in the spec, naming the case.
  const std::filesystem::path unknown = write_spec("bad_set_key", "load_cases:\n  - name: s\n    set: {controller.gain_typo: [1]}\n");
  const std::string unknown_message = error_of(unknown);
  CHECK_THAT(unknown_message, Catch::Contains(unknown.string() + ":7:11: controller.gain_typo: unknown key"));
  CHECK_THAT(unknown_message, Catch::Contains("case s"));
}
