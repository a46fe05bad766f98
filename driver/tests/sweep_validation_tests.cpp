// Every case deck is checked as `fowtsim run` reads it before anything runs (issue 22, item 11):
// the shipped example's DLC 6.1 preset once set min_pitch_rad above the deck's max_pitch_rad and
// 3 of its 9 cases failed only when run; neither --list nor --slurm --dry-run said so.
#include <catch2/catch.hpp>

#include <fstream>

#include "fowtsim/testing/skip.hpp"
#include "run/validate_deck.hpp"
#include "sweep/case_expansion.hpp"
#include "sweep/case_files.hpp"
#include "sweep/sweep_spec.hpp"
#include "sweep_test_spec.hpp"

using namespace fowtsim;
using namespace fowtsim::sweep_test;

TEST_CASE("sweep example: every case deck passes the run's checks with DLC 6.1 idling at the deck's pitch limit",
          "[unit][sweep]") {
  const std::filesystem::path dir = testing::scratch_dir("sweep_example_decks");
  const driver::sweep::SweepSpec spec = driver::sweep::read_sweep_spec(testing::source_dir() / "inputs/sweeps/dlc12_oc3.yaml");
  const auto cases = driver::sweep::expand_cases(spec, driver::sweep::read_base_deck_facts(spec.base_deck));
  REQUIRE(cases.size() == 9);
  const driver::sweep::SweepLayout layout{dir / "out"};
  const std::vector<std::string> hashes = driver::sweep::write_case_decks(spec, cases, layout);
  CHECK(hashes.size() == 9);
  // The idling cases' own check, as `fowtsim run` applies it (the controller's pitch limits):
  // feathered at the deck's max_pitch_rad 1.570796 rad = 90.00000459°, no limit moved.
  for (const char* name : {"dlc61_yaw-8", "dlc61_yaw0", "dlc61_yaw8"}) {
    INFO(name);
    CHECK_NOTHROW(driver::validate_scene_deck(layout.deck(name)));
    CHECK_THAT(read_text(layout.deck(name)), Catch::Contains("operating_mode: idling\n") && !Catch::Contains("min_pitch_rad"));
  }
  // --list checks the same decks and succeeds.
  CHECK(run_fowtsim("sweep " + (testing::source_dir() / "inputs/sweeps/dlc12_oc3.yaml").string() + " --list --output-dir " +
                        (dir / "listed").string(),
                    dir / "list.log") == 0);
}

// Intent: --base-deck runs the spec's cases on another model: the case decks include that deck,
// with the same seeds (they derive from the spec, not from the model).
TEST_CASE("sweep --base-deck: the same cases and seeds on another deck", "[unit][sweep]") {
  const std::filesystem::path dir = testing::scratch_dir("sweep_base_deck");
  const std::filesystem::path spec = testing::source_dir() / "inputs/sweeps/dlc12_oc3.yaml";
  const std::filesystem::path fast = testing::source_dir() / "inputs/oc3_hywind/turbine_ntm_12mps_irregular_fast.yaml";
  REQUIRE(run_fowtsim("sweep " + spec.string() + " --slurm --dry-run --output-dir " + (dir / "spec").string(), dir / "spec.log") == 0);
  REQUIRE(run_fowtsim("sweep " + spec.string() + " --slurm --dry-run --base-deck " + fast.string() + " --output-dir " +
                          (dir / "fast").string(),
                      dir / "fast.log") == 0);
  const std::string original = read_text(dir / "spec/decks/dlc12_ws12_s1.yaml");
  const std::string other = read_text(dir / "fast/decks/dlc12_ws12_s1.yaml");
  CHECK_THAT(other, Catch::Contains("turbine_ntm_12mps_irregular_fast.yaml"));
  CHECK_THAT(original, !Catch::Contains("_fast.yaml"));
  const auto seed_line = [](const std::string& text) { return text.substr(text.find("seed:"), text.find('\n', text.find("seed:")) - text.find("seed:")); };
  CHECK(seed_line(original) == seed_line(other));
  // The folder of the --base-deck sweep is bound to its deck: the same sweep without it (a forgotten
  // option, --collect say) stops before any case deck changes.
  CHECK(run_fowtsim("sweep " + spec.string() + " --collect --output-dir " + (dir / "fast").string(), dir / "forgot.log") == 2);
  CHECK_THAT(read_text(dir / "forgot.log"), Catch::Contains("holds the cases of the base deck") && Catch::Contains("--base-deck"));
  CHECK(read_text(dir / "fast/decks/dlc12_ws12_s1.yaml") == other);
}

TEST_CASE("sweep: a case deck `fowtsim run` would reject stops --list and --slurm --dry-run and a local run before anything",
          "[unit][sweep]") {
  const std::filesystem::path dir = testing::scratch_dir("sweep_rejected_case");
  // A lower pitch limit above the deck's max_pitch_rad 1.570796 (π/2, the value an early DLC 6.1
  // preset set) makes every case one the run refuses.
  const std::filesystem::path spec = dir / "spec.yaml";
  std::ofstream(spec) << "sweep:\n  name: parked\n  base_deck: "
                      << (testing::source_dir() / "inputs/oc3_hywind/turbine_ntm_12mps_irregular.yaml").string() << R"(
  transient_s: 10
  analysis_s: 20
load_cases:
  - name: p
    preset: dlc6.1
    seeds: 1
    sea_state: {hs_m: 6.0, tp_s: 12.0}
    set: {controller.min_pitch_rad: [1.5707963267948966]}
)";
  const std::filesystem::path out = dir / "out";
  std::filesystem::remove_all(out);
  const std::string sweep = "sweep " + spec.string() + " --output-dir " + out.string();
  for (const std::string action : {" --list", " --slurm --dry-run", " --jobs 1"}) {
    INFO(action);
    REQUIRE(run_fowtsim(sweep + action, dir / "rejected.log") == 2);
    const std::string log = read_text(dir / "rejected.log");
    INFO(log);
    // Each case by name, its deck's file:line and the key concerned.
    for (const char* name : {"p_yaw-8", "p_yaw0", "p_yaw8"}) CHECK_THAT(log, Catch::Contains(name));
    CHECK_THAT(log, Catch::Contains((out / "decks" / "p_yaw0.yaml").string() + ":"));
    CHECK_THAT(log, Catch::Contains("controller.max_pitch_rad: expected a finite value ≥ min_pitch_rad"));
  }
  // Nothing ran and nothing was submitted: no output, no log, no job script.
  CHECK(std::filesystem::is_empty(out / "cases"));
  CHECK(std::filesystem::is_empty(out / "logs"));
  CHECK_FALSE(std::filesystem::exists(out / "slurm" / "sweep.sbatch"));
}
