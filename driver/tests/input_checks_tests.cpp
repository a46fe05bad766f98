// Implausible or misplaced inputs (issue 22, items 9 and 10) stop before anything is written, as
// input errors at the deck line that holds them: initial conditions out of sense, a mooring the
// initial pose overstretches, a directory where a file belongs, a negative beam mass per length.
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/testing/skip.hpp"
#include "run/run_scene.hpp"
#include "run_request.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

// The message of the InputError that running `deck` (writing dir/run) throws; fails if none.
std::string input_error_of(const std::filesystem::path& deck, const std::filesystem::path& dir) {
  try {
    run_scene(run_request(deck, dir / "run", std::nullopt), nullptr);
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("no InputError for " << deck);
  return "";
}

// A deck in `dir` that includes the shipped `shipped` (relative to inputs/) and adds `extra`.
std::filesystem::path deck_over(const std::filesystem::path& dir, const std::string& shipped, const std::string& extra) {
  std::ofstream(dir / "deck.yaml") << "include: [" << (testing::source_dir() / "inputs" / shipped).string() << "]\n" << extra;
  return dir / "deck.yaml";
}

bool nothing_written(const std::filesystem::path& dir) {
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().filename() != "deck.yaml" && entry.path().filename() != "data") return false;
  return true;
}

}  // namespace

TEST_CASE("initial conditions out of sense stop at their deck line", "[unit][run]") {
  // Intent: a position of 1e300 m used to stop "in mooring at t = 0" (exit 3) and a heave of 1e19 m
  // got "use more load steps"; each out-of-sense value is an input error at its line, nothing written.
  const auto dir = testing::scratch_dir("input_checks_initial");
  const std::string ic = "structure:\n  initial_conditions:\n";
  struct Case {
    std::string yaml, expected;
  };
  const Case cases[] = {
      {"    platform_position_m: [1e300, 0, 0]\n", "platform_position_m[0]: expected a number >= -1000 and <= 1000"},
      {"    platform_position_m: [0, 0, 1e19]\n", "platform_position_m[2]: expected a number >= -1000 and <= 1000"},
      {"    platform_position_m: [0, 0, 150]\n", "heave 150 m: expected within ±100 m"},
      {"    platform_angles_deg: [0, 95, 0]\n", "pitch 95°: expected within ±90°"},
      {"    platform_velocity_m_s: [0, 0, 80]\n", "platform_velocity_m_s[2]: expected a number >= -50 and <= 50"},
      {"    blade_pitch_deg: 120\n", "blade_pitch_deg: expected a number >= -90 and <= 90"},
      {"    rotor_speed_rpm: 90\n", "90 rpm turns the 63-m blade tip at 594 m/s"},
  };
  for (const Case& c : cases) {
    const auto deck = deck_over(dir, "oc3_hywind/free_decay_heave.yaml", ic + c.yaml);
    const std::string message = input_error_of(deck, dir);
    CHECK_THAT(message, Catch::Contains("deck.yaml:4:") && Catch::Contains(c.expected));
    CHECK(nothing_written(dir));
  }
}

TEST_CASE("an initial position that overstretches a mooring line stops at the position's line", "[unit][run]") {
  // Intent: 999 m of surge passes the ±1000 m bound but stretches OC3's line 2 (902.2 m) by 80 %;
  // the bound depends on the mooring, so the scene checks it. 20 m (free_decay_surge) still runs.
  const auto dir = testing::scratch_dir("input_checks_mooring");
  const auto deck = deck_over(dir, "oc3_hywind/free_decay_heave.yaml",
                              "structure:\n  initial_conditions:\n    platform_position_m: [999, 0, 0]\n");
  CHECK_THAT(input_error_of(deck, dir), Catch::Contains("deck.yaml:4:") && Catch::Contains("line 2 spans 1621.3 m") &&
                                            Catch::Contains("80 % more than its unstretched length 902.2 m"));
  CHECK(nothing_written(dir));
}

TEST_CASE("a directory where a deck names a file to read stops at the key", "[unit][run]") {
  // Intent: "no such file" or "no data lines" sent users looking for a missing file; the key's
  // file:line and "is a directory" say what is wrong.
  const auto dir = testing::scratch_dir("input_checks_directory");
  std::filesystem::create_directories(dir / "field.bts");
  const auto wind = deck_over(dir, "oc3_hywind/turbine_steady_15mps.yaml", "wind: {model: bts, file: field.bts}\n");
  CHECK_THAT(input_error_of(wind, dir), Catch::Contains("deck.yaml:2:") && Catch::Contains("wind.file") &&
                                            Catch::Contains("field.bts is a directory, not a file"));
  std::filesystem::create_directories(dir / "record.txt");
  const auto waves = deck_over(dir, "oc3_hywind/sea_replay_example.yaml", "waves: {file: record.txt}\n");
  CHECK_THAT(input_error_of(waves, dir), Catch::Contains("deck.yaml:2:") && Catch::Contains("waves.file") &&
                                             Catch::Contains("record.txt is a directory, not a file"));
  std::filesystem::create_directories(dir / "primary.inp");
  const auto beam = deck_over(dir, "beams/rollup.yaml", "beam: {beamdyn_file: primary.inp}\n");
  CHECK_THAT(input_error_of(beam, dir), Catch::Contains("beam.beamdyn_file") && Catch::Contains("is a directory, not a file"));
}

TEST_CASE("a negative beam mass per length names the deck key of its station", "[unit][run]") {
  // Intent: "beam: mass per length must be ≥ 0" had no location; it now points at stations[i].mass.
  const auto dir = testing::scratch_dir("input_checks_beam_mass");
  std::ifstream in(testing::source_dir() / "inputs/beams/rollup.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), {});
  const auto second = text.find("mass: [1,", text.find("eta: 1.0"));
  REQUIRE(second != std::string::npos);
  text.replace(second, 9, "mass: [-1,");
  std::ofstream(dir / "deck.yaml") << text;
  CHECK_THAT(input_error_of(dir / "deck.yaml", dir),
             Catch::Contains("deck.yaml:31:") && Catch::Contains("beam.stations[1].mass: mass per length must be ≥ 0"));
  CHECK(nothing_written(dir));
}

TEST_CASE("Rayleigh-Ritz blade decks: a missing blade file, a second blade model or a tip radius that disagrees stop at the deck", "[unit][run]") {
  const auto dir = testing::scratch_dir("input_checks_rr");
  std::string message = input_error_of(deck_over(dir, "nrel5mw/onshore_startup_rr.yaml", "structure: {rotor: {rayleigh_ritz_blade_file: nope.yaml}}\n"), dir);
  CHECK_THAT(message, Catch::Contains("deck.yaml:2:") && Catch::Contains("rayleigh_ritz_blade_file") && Catch::Contains("does not exist"));
  CHECK(nothing_written(dir));
  message = input_error_of(deck_over(dir, "oc3_hywind/turbine_flexible_ntm_12mps_irregular.yaml",
                                     "structure: {rotor: {rayleigh_ritz_blade_file: " +
                                         (testing::source_dir() / "inputs/nrel5mw/blade_elastodyn.yaml").string() + "}}\n"),
                           dir);
  CHECK_THAT(message, Catch::Contains("deck.yaml:2:") && Catch::Contains("one blade model"));
  CHECK(nothing_written(dir));
  message = input_error_of(deck_over(dir, "nrel5mw/onshore_startup_rr.yaml", "structure: {rotor: {tip_radius_m: 62.0}}\n"), dir);
  CHECK_THAT(message, Catch::Contains("rayleigh_ritz_blade.tip_radius_m") && Catch::Contains("62"));
  CHECK(nothing_written(dir));
}

TEST_CASE("MBBT blades on the flexible tower: a split large step and a held rotor speed stop at their deck line",
          "[unit][run][flexible]") {
  // Both diverged when they ran (modules/multibody/README.md, "Flexible tower with MBBT blades"): RK4
  // substeps inside the large step broke the interface mass's match (ΔT 40 ms in 20-ms steps, 488 s),
  // and a held rotor speed hands the blades' torque about the shaft to the tower top explicitly.
  const auto dir = testing::scratch_dir("input_checks_mbbt_flexible_tower");
  const std::string deck = "oc3_hywind/turbine_flexible_ntm_12mps_irregular.yaml";
  CHECK_THAT(input_error_of(deck_over(dir, deck, "simulation: {dt_s: 0.04}\nstructure: {tower: {flexible: true}}\n"), dir),
             Catch::Contains("structure.max_step_s: 0.025 s splits each large step of 0.04 s") &&
                 Catch::Contains("one RK4 step per large step"));
  CHECK(nothing_written(dir));
  CHECK_THAT(input_error_of(deck_over(dir, deck, "structure: {tower: {flexible: true}, degrees_of_freedom: {rotor_speed: held}}\n"), dir),
             Catch::Contains("a held rotor speed with MBBT blades on the flexible tower is not supported"));
  CHECK(nothing_written(dir));
  // The same keys on the rigid tower run as before: checked by the stability map's points and the
  // seed's validation deck (rigid tower, speed held) in their own tests.
}
