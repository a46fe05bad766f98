// Channels named as OpenFAST's mean what OpenFAST's mean (issue 23): the first row carries the
// controller's demands of t = 0 and the blades' actual pitch; ServoDyn's command has its own name.
#include <fstream>

#include <catch2/catch.hpp>

#include "fowtsim/io/readers.hpp"
#include "fowtsim/testing/skip.hpp"
#include "run/run_scene.hpp"
#include "run_request.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

double at_row(const io::ChannelTable& t, const char* name, std::size_t row) {
  const auto c = t.find(name);
  REQUIRE(c);
  return t.columns[*c][row];
}

io::ChannelTable run_short(const std::string& name, const std::string& deck_text) {
  const auto dir = testing::scratch_dir(name);
  std::ofstream(dir / "deck.yaml") << deck_text;
  RunRequest r = run_request(dir / "deck.yaml", dir / "run", "h5");
  r.t_max_s = 0.2;
  run_scene(r, nullptr);
  return io::read_channels(dir / "run.h5");
}

}  // namespace

TEST_CASE("the first row: the controller's demands of t = 0 and the blades' pitch of the initial conditions",
          "[unit][run]") {
  const std::string inputs = (testing::source_dir() / "inputs/oc3_hywind").string();
  // Flexible blades starting at 5° of pitch in 12 m/s: ElastoDyn's BldPitch1 is the blade's own
  // pitch (5° at t = 0), ServoDyn's BlPitchC1 the controller's command, GenTq its torque demand
  // at the initial generator speed (not the 0 of a controller not yet called).
  const io::ChannelTable flexible = run_short(
      "first_row_flexible", "include: [" + inputs + "/turbine_flexible_ntm_12mps_irregular.yaml]\n"
                                "structure: {initial_conditions: {blade_pitch_deg: 5.0}}\n");
  CHECK(at_row(flexible, "BldPitch1", 0) == Approx(5.0).epsilon(1e-12));
  CHECK(at_row(flexible, "BldPitchAct1", 0) == at_row(flexible, "BldPitch1", 0));
  CHECK(at_row(flexible, "GenTq", 0) > 30.0);  // kN·m: near the 43.09 rated torque at 12.1 rpm
  CHECK(at_row(flexible, "GenTq", 0) == at_row(flexible, "GenTq", 1));  // held over the first step
  CHECK(at_row(flexible, "GenPwr", 0) > 0.0);
  REQUIRE(flexible.find("BlPitchC1"));
  // Rigid blades turn to the held demand at once: their pitch is the command of the row's time.
  const io::ChannelTable rigid =
      run_short("first_row_rigid", "include: [" + inputs + "/turbine_steady_15mps.yaml]\n"
                                       "structure: {initial_conditions: {blade_pitch_deg: 5.0}}\n");
  CHECK(at_row(rigid, "GenTq", 0) > 30.0);
  CHECK(at_row(rigid, "BldPitch1", 0) == at_row(rigid, "BlPitchC1", 0));
  CHECK(at_row(rigid, "BldPitch1", 1) == at_row(rigid, "BlPitchC1", 1));
}
