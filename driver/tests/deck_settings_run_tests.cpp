// `fowtsim run DECK --set key.path=value` (issue 23): a variant without a new deck file. The run
// takes the settings, its outputs record them (deck hash, HDF5 deck_settings), and a checkpoint
// continues only under the same settings.
#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/testing/skip.hpp"
#include "h5_attributes.hpp"
#include "run/run_scene.hpp"
#include "run_request.hpp"
#include "test_helpers.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

std::filesystem::path toy_deck() { return testing::source_dir() / "inputs/toy_coupled_oscillators.yaml"; }

}  // namespace

TEST_CASE("a run with --set runs the deck with the keys set, and the output records them", "[unit][run]") {
  const auto dir = testing::scratch_dir("set_run");
  RunRequest plain = run_request(toy_deck(), dir / "plain", "h5");
  plain.t_max_s = 2.0;
  run_scene(plain, nullptr);
  RunRequest set = run_request(toy_deck(), dir / "set", "h5");
  set.deck_settings = {"simulation.t_max_s=1.5", "simulation.dt_coupling_s=0.025"};
  const RunReport report = run_scene(set, nullptr);
  CHECK(report.simulated_s == Approx(1.5));
  const io::ChannelTable table = io::read_channels(dir / "set.h5");
  CHECK(table.rows() == 61);  // 1.5 s in steps of 0.025 s
  CHECK(string_attribute(dir / "set.h5", "deck_settings") == "simulation.t_max_s=1.5\nsimulation.dt_coupling_s=0.025");
  CHECK(string_attribute(dir / "set.h5", "deck_hash") != string_attribute(dir / "plain.h5", "deck_hash"));
}

TEST_CASE("a run with a wrong --set stops before any file, naming the setting and the key", "[unit][run]") {
  const auto dir = testing::scratch_dir("set_errors");
  RunRequest r = run_request(toy_deck(), dir / "x", "h5");
  r.deck_settings = {"simulation.t_max=3"};
  CHECK_THAT(message_of([&] { run_scene(r, nullptr); }),
             Catch::Contains("--set simulation.t_max: simulation.t_max: unknown key") && Catch::Contains("did you mean `t_max_s`?"));
  CHECK(std::filesystem::is_empty(dir));
}

TEST_CASE("a checkpoint written under --set continues only under the same settings", "[unit][run]") {
  const auto dir = testing::scratch_dir("set_restart");
  RunRequest first = run_request(toy_deck(), dir / "first", "h5");
  first.t_max_s = 2.0;
  first.checkpoint_every_s = 1.5;  // one checkpoint, before the end
  first.deck_settings = {"simulation.seed=5"};
  run_scene(first, nullptr);
  RunRequest without = run_request(toy_deck(), dir / "without", "h5");
  without.t_max_s = 2.0;
  without.restart_path = dir / "first.chk";
  CHECK_THROWS_AS(run_scene(without, nullptr), InputError);
  CHECK_FALSE(std::filesystem::exists(dir / "without.h5"));
  RunRequest same = without;
  same.output_base = dir / "same";
  same.deck_settings = first.deck_settings;
  run_scene(same, nullptr);
  CHECK(io::read_channels(dir / "same.h5").columns == io::read_channels(dir / "first.h5").columns);
}
