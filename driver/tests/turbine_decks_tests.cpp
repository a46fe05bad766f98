// The turbine decks the driver reads for issue 4: the NREL 5MW aero deck maps onto aero::Params,
// bad aero rows stop with file:line, and `fowtsim turbulence` writes a .bts the io reader reads
// back, deterministically.
#include <fstream>

#include <catch2/catch.hpp>

#include "run/turbulence_command.hpp"
#include "decks/aero_deck.hpp"
#include "decks/beam_deck.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/io/turbsim_bts.hpp"
#include "fowtsim/testing/skip.hpp"
#include "run/run_scene.hpp"
#include "scenes/floating_scene.hpp"
#include "run_request.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {
io::Schema aero_deck_schema() { return io::Schema::map({{"aero", aero_schema()}, {"airfoils", airfoils_schema()}}); }
}  // namespace

TEST_CASE("the NREL 5MW aero deck reads into the aero parameters", "[unit][decks]") {
  const aero::Params p = aero_params(io::read_deck(aero_deck_schema(), testing::source_dir() / "inputs/nrel5mw/aero.yaml"));
  // AeroDyn blade file of the 5MW baseline: 19 nodes, 8 airfoils, tip at BlSpn 61.4999 m, tip
  // chord 1.419 m, root twist 13.308°.
  CHECK(p.blade.size() == 19);
  CHECK(p.airfoils.size() == 8);
  CHECK(p.blade.back().span_m == 61.4999);
  CHECK(p.blade.back().chord_m == 1.419);
  CHECK(p.blade.front().twist_rad == Approx(13.308 * 3.14159265358979323846 / 180.0).epsilon(1e-15));
  CHECK(p.airfoils[static_cast<std::size_t>(p.blade.back().airfoil)].name() == "NACA64_A17");
}

TEST_CASE("an aero blade row naming an unknown airfoil stops with file and line", "[unit][decks]") {
  const auto dir = testing::scratch_dir("aero_deck_bad");
  const auto deck = dir / "aero.yaml";
  std::ofstream(deck) << "airfoils:\n  - {name: flat, polar: [[-180, 0, 0.01, 0], [180, 0, 0.01, 0]]}\n"
                         "aero:\n  blade:\n    nodes:\n      - [0, 0, 0, 0, 0, 1, flat]\n      - [10, 0, 0, 0, 0, 1, round]\n";
  CHECK_THROWS_WITH(aero_params(io::read_deck(aero_deck_schema(), deck)),
                    Catch::Contains("aero.yaml:7") && Catch::Contains("unknown airfoil 'round'"));
}

TEST_CASE("fowtsim turbulence writes a .bts that reads back, the same for the same seed", "[unit][decks]") {
  const auto dir = testing::scratch_dir("turbulence_command");
  const auto deck = dir / "wind.yaml";
  std::ofstream(deck) << "wind:\n  model: turbulent\n  speed_m_s: 10\n  reference_height_m: 90\n"
                         "  turbulence: {ny: 5, nz: 4, width_m: 40, height_m: 30, dt_s: 0.25, duration_s: 64, seed: 3}\n";
  std::FILE* sink = std::tmpfile();
  REQUIRE(run_turbulence_command(deck, dir / "a", sink) == 0);
  REQUIRE(run_turbulence_command(deck, dir / "b", sink) == 0);
  std::fclose(sink);
  const io::TurbSimField a = io::read_turbsim_bts(dir / "a.bts"), b = io::read_turbsim_bts(dir / "b.bts");
  CHECK(a.ny == 5);
  CHECK(a.nz == 4);
  CHECK(a.nt == 256);  // 64 s at 0.25 s, periodic
  CHECK(a.grid == b.grid);
  CHECK(std::filesystem::exists(dir / "a.h5"));
}

TEST_CASE("a floating deck whose aero blade disagrees with the structure stops before the run", "[unit][decks]") {
  const auto dir = testing::scratch_dir("floating_rotor_mismatch");
  const auto deck = dir / "turbine.yaml";
  std::ofstream(deck) << "include: [" << (testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml").string() << "]\n"
                      << "aero: {number_of_blades: 2}\n";
  CHECK_THROWS_WITH(run_scene(run_request(deck, dir / "run", std::nullopt), nullptr), Catch::Contains("turbine.yaml:2") && Catch::Contains("2 blades, the structure has 3"));
}

TEST_CASE("blades read from the BeamDyn files of the OpenFAST deck equal the transcribed blade deck", "[verification][decks]") {
  // blades.beamdyn_file names OpenFAST's BeamDyn primary input (which names the blade file): the
  // same reference line, 49 stations and damping as inputs/nrel5mw/blade_structure.yaml, which was
  // transcribed from these files. Stations and damping are the files' numbers (exact); the line is
  // the same polynomial fit (rounding: 1e-12 m).
  const auto shared = testing::shared_dir_or_skip();
  const auto dir = testing::scratch_dir("blades_from_beamdyn");
  const auto inputs = testing::source_dir() / "inputs";
  const std::string base = "include: [" + (inputs / "oc3_hywind/turbine_flexible_ntm_12mps_irregular.yaml").string() + "]\n";
  std::ofstream(dir / "transcribed.yaml") << base;
  // The shipped deck includes blade_structure.yaml; its key points, twist and stations are left
  // out here by building the same deck from the other includes.
  std::ofstream(dir / "beamdyn.yaml")
      << "include: [" << (inputs / "oc3_hywind/structure.yaml").string() << ", " << (inputs / "nrel5mw/aero.yaml").string()
      << "]\nsimulation: {t_max_s: 1.0, dt_s: 0.02}\nwind: {model: steady, speed_m_s: 12.0, reference_height_m: 90.0}\n"
      << "blades: {beamdyn_file: "
      << (shared / "reference/r-test/glue-codes/openfast/5MW_Baseline/NRELOffshrBsline5MW_BeamDyn.dat").string() << "}\n";
  const beam::BeamDefinition ours = beam_definition(io::read_deck(floating_scene_schema(), dir / "transcribed.yaml"), "blades");
  const beam::BeamDefinition theirs = beam_definition(io::read_deck(floating_scene_schema(), dir / "beamdyn.yaml"), "blades");
  REQUIRE(theirs.stations.size() == 49);
  REQUIRE(ours.stations.size() == theirs.stations.size());
  for (std::size_t i = 0; i < ours.stations.size(); ++i) {
    CHECK(ours.stations[i].eta == theirs.stations[i].eta);
    CHECK(ours.stations[i].stiffness == theirs.stations[i].stiffness);
    CHECK(ours.stations[i].mass == theirs.stations[i].mass);
  }
  CHECK(ours.stiffness_damping == theirs.stiffness_damping);
  CHECK(ours.line.length_m() == Approx(theirs.line.length_m()).epsilon(1e-12));
  for (const double s : {0.0, 10.0, 30.0, 61.5}) {
    const beam::LinePoint a = ours.line.at(s), b = theirs.line.at(s);
    CHECK((a.position_m - b.position_m).norm() < 1e-12);
    CHECK((a.frame - b.frame).norm() < 1e-12);
  }
  // Both ways at once is refused at the deck key.
  std::ofstream(dir / "both.yaml") << base << "blades: {beamdyn_file: x.dat}\n";
  CHECK_THROWS_WITH(beam_definition(io::read_deck(floating_scene_schema(), dir / "both.yaml"), "blades"),
                    Catch::Contains("both.yaml") || Catch::Contains("remove key_points_m"));
}
