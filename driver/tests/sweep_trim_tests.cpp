// Trimmed initial conditions (issue 27): a steady run per wind speed gives the operating point
// each operating case starts from; in steady wind the trimmed case then starts where it would
// settle, while the base deck's initial state swings through a start-up transient.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>

#include "fowtsim/io/readers.hpp"
#include "fowtsim/post/statistics.hpp"
#include "fowtsim/testing/skip.hpp"
#include "sweep/case_expansion.hpp"
#include "sweep/trim.hpp"
#include "sweep_test_spec.hpp"

using namespace fowtsim;
using namespace fowtsim::sweep_test;

namespace {

std::filesystem::path write_spec(const std::filesystem::path& dir, const std::string& name, bool trim) {
  const std::filesystem::path spec = dir / (name + ".yaml");
  std::ofstream(spec) << "sweep:\n  name: " << name << "\n  base_deck: "
                      << (testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml").string() << "\n  output_dir: "
                      << (dir / name).string() << "\n  transient_s: 0\n  analysis_s: 60\n"
                      << (trim ? "  trim: {duration_s: 300, average_s: 125}\n" : "")
                      << "load_cases:\n  - {name: steady, wind_speeds_m_s: [16]}\n";
  return spec;
}

post::ChannelStatistics statistics(const std::filesystem::path& h5, const char* channel) {
  const io::ChannelTable t = io::read_hdf5_channels(h5);
  return post::channel_statistics(t.time(), t.columns.at(t.find(channel).value()));
}

}  // namespace

TEST_CASE("sweep trim: a case started at its steady operating point has no start-up transient", "[verification][sweep]") {
  const std::filesystem::path dir = testing::scratch_dir("sweep_trim");
  REQUIRE(run_fowtsim("sweep " + write_spec(dir, "trimmed", true).string() + " --jobs 1", dir / "trimmed.log") == 0);
  REQUIRE(run_fowtsim("sweep " + write_spec(dir, "plain", false).string() + " --jobs 1", dir / "plain.log") == 0);
  INFO(read_text(dir / "trimmed.log"));
  const std::string deck = read_text(dir / "trimmed/decks/steady_ws16.yaml");
  CHECK_THAT(deck, Catch::Contains("rotor_speed_rpm:") && Catch::Contains("blade_pitch_deg:") && Catch::Contains("platform_position_m: ["));
  const auto trimmed = dir / "trimmed/cases/steady_ws16.h5", plain = dir / "plain/cases/steady_ws16.h5";
  // Over the first 60 s at 16 m/s, steady wind, still water. Measured: trimmed RotSpeed std 0.022 rpm,
  // BldPitch1 0.026°, PtfmPitch 0.025° (what is left of the 125-s surge oscillation averaged over one
  // period); from the base deck's 12.1 rpm, 0° pitch: 1.35 rpm, 2.80°, 2.65°. Bounds ~10× the trimmed ones.
  CHECK(statistics(trimmed, "RotSpeed").std < 0.2);
  CHECK(statistics(trimmed, "BldPitch1").std < 0.25);
  CHECK(statistics(trimmed, "PtfmPitch").std < 0.25);
  CHECK(statistics(plain, "RotSpeed").std > 5.0 * statistics(trimmed, "RotSpeed").std);
  CHECK(statistics(plain, "PtfmPitch").std > 5.0 * statistics(trimmed, "PtfmPitch").std);

  SECTION("the trim runs are cached: a rerun runs neither them nor the completed case") {
    REQUIRE(run_fowtsim("sweep " + (dir / "trimmed.yaml").string() + " --jobs 1", dir / "rerun.log") == 0);
    CHECK_THAT(read_text(dir / "rerun.log"), Catch::Contains("1 steady run(s) of 300 s (1 cached)") &&
                                                 Catch::Contains("(1 completed earlier and skipped), 0 to run"));
  }
}

TEST_CASE("sweep trim: Rayleigh-Ritz blades start at their static deflection, other blades are left alone", "[unit][sweep]") {
  // The base deck's facts say whether it has Rayleigh–Ritz blades; the trim then adds
  // structure.initial_conditions.blade_deflection: static (MBBT blades start static by blades.start).
  const std::filesystem::path dir = testing::scratch_dir("sweep_trim_rr");
  const auto inputs = testing::source_dir() / "inputs";
  std::ofstream(dir / "rr.yaml") << "include: [" << (inputs / "oc3_hywind/turbine_steady_15mps.yaml").string()
                                 << "]\nstructure: {rotor: {rayleigh_ritz_blade_file: "
                                 << (inputs / "nrel5mw/blade_elastodyn.yaml").string() << "}}\n";
  CHECK(driver::sweep::read_base_deck_facts(dir / "rr.yaml").rayleigh_ritz_blades);
  CHECK_FALSE(driver::sweep::read_base_deck_facts(inputs / "oc3_hywind/turbine_steady_15mps.yaml").rayleigh_ritz_blades);
  for (const bool rr : {true, false}) {
    std::vector<driver::sweep::SweepCase> cases(1);
    cases[0].name = "c";
    cases[0].wind_speed_m_s = 16.0;
    driver::sweep::apply_trim(cases, {{16.0, driver::sweep::OperatingPoint{}}}, rr);
    const bool has = std::any_of(cases[0].overrides.begin(), cases[0].overrides.end(), [](const driver::sweep::DeckOverride& o) {
      return o.key_path == "structure.initial_conditions.blade_deflection" && o.yaml_value == "static";
    });
    CHECK(has == rr);
  }
}
