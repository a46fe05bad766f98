// A run owns its files (issue 22): one run per output name, a folder is not a file name, a dead
// run's temporaries are kept, checkpoints are whole or refused as damaged, a checkpoint is never
// ahead of the rows, and a restart continues the interrupted output instead of replacing it.
#include <signal.h>
#include <unistd.h>

#include <fstream>
#include <iterator>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/testing/skip.hpp"
#include "h5_attributes.hpp"
#include "run/interrupt.hpp"
#include "run/output_set.hpp"
#include "run/run_scene.hpp"
#include "run_request.hpp"
#include "test_helpers.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

const std::vector<ChannelInfo> kOneChannel = {ChannelInfo{"X", "m", "x", "test"}};

std::string bytes_of(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void append_row(OutputSet& set, double t) { set.append(t, std::span<const double>(&t, 1)); }

std::filesystem::path toy_deck() { return testing::source_dir() / "inputs/toy_coupled_oscillators.yaml"; }

}  // namespace

TEST_CASE("a second run on a live run's output name stops before touching it, naming the holder", "[unit][run]") {
  const auto dir = testing::scratch_dir("own_lock");
  {
    OutputSet first(dir / "x", "both");
    first.begin(kOneChannel, io::RunMetadata{});
    append_row(first, 0.0);
    first.sync();
    const std::string live = bytes_of(dir / "x.running.out");
    const std::string message = message_of([&] { OutputSet second(dir / "x", "both"); });
    CHECK_THAT(message, Catch::Contains("being written by another run") && Catch::Contains(fmt::format("PID {}", ::getpid())));
    // The first run's temporaries are untouched and it finishes under the final names.
    CHECK(bytes_of(dir / "x.running.out") == live);
    CHECK(std::filesystem::exists(dir / "x.running.h5"));
    append_row(first, 1.0);
    first.finish({0.0, "completed", 1.0, {}});
  }
  CHECK(io::read_channels(dir / "x.h5").rows() == 2);
  CHECK(io::read_channels(dir / "x.out").rows() == 2);
  CHECK(io::read_channels(dir / "x.out").status == "completed");
  CHECK_FALSE(std::filesystem::exists(dir / "x.lock"));  // released: a later run may take the name
  OutputSet later(dir / "x", "h5");
}

TEST_CASE("an output name that is a folder stops before the run", "[unit][run]") {
  const auto dir = testing::scratch_dir("own_folder");
  std::filesystem::create_directories(dir / "taken.h5");
  RunRequest r = run_request(toy_deck(), dir / "taken.h5", std::nullopt);
  CHECK_THAT(message_of([&] { run_scene(r, nullptr); }), Catch::Contains("is a folder"));
  CHECK(std::filesystem::is_empty(dir / "taken.h5"));
}

TEST_CASE("a temporary left by a dead run is kept as .unfinished, never overwritten", "[unit][run]") {
  const auto dir = testing::scratch_dir("own_unfinished");
  std::ofstream(dir / "x.running.out") << "rows of a run that was killed\n";
  OutputSet set(dir / "x", "out");
  REQUIRE(set.set_aside().size() == 1);
  CHECK(set.set_aside().front() == dir / "x.unfinished.out");
  CHECK(bytes_of(dir / "x.unfinished.out") == "rows of a run that was killed\n");
  REQUIRE(set.notes().size() == 1);
  CHECK_THAT(set.notes().front(), Catch::Contains("kept as"));
}

TEST_CASE("the .out says on line 5 how its run ended; a row cut short is dropped with a warning", "[unit][run]") {
  const auto dir = testing::scratch_dir("own_status");
  {
    OutputSet set(dir / "x", "out");
    set.begin(kOneChannel, io::RunMetadata{});
    append_row(set, 0.0);
    append_row(set, 0.5);
    set.finish({0.0, "interrupted at t = 0.5 s (SIGTERM)", 0.5, {}});
  }
  std::ifstream in(dir / "x.out");
  std::string line;
  for (int n = 1; n <= 7; ++n) std::getline(in, line);
  CHECK(line == "Time\tX");  // OpenFAST's layout: names on line 7
  const io::ChannelTable table = io::read_channels(dir / "x.out");
  CHECK(table.status == "interrupted at t = 0.5 s (SIGTERM)");
  CHECK(io::reading_warnings(table, "x.out").size() == 1);
  // A kill mid-row leaves a last line without its newline: the whole rows are read.
  const std::string whole = bytes_of(dir / "x.out");
  std::ofstream(dir / "cut.out", std::ios::binary) << whole << " 1.00000";
  const io::ChannelTable cut = io::read_channels(dir / "cut.out");
  CHECK(cut.rows() == 2);
  REQUIRE(cut.warnings.size() == 1);
  CHECK_THAT(cut.warnings.front(), Catch::Contains("cut short"));
  // The same partial row with its newline is a malformed file, not a cut one.
  std::ofstream(dir / "bad.out", std::ios::binary) << whole << " 1.00000\n";
  CHECK_THROWS_AS(io::read_channels(dir / "bad.out"), InputError);
}

TEST_CASE("a damaged checkpoint is named as damaged, not as another deck's", "[unit][run]") {
  const auto dir = testing::scratch_dir("own_damaged_checkpoint");
  RunRequest r = run_request(toy_deck(), dir / "run", "h5");
  r.t_max_s = 2.0;
  r.checkpoint_every_s = 1.0;
  run_scene(r, nullptr);
  const std::string good = bytes_of(dir / "run.chk");
  RunRequest restart = run_request(toy_deck(), dir / "again", "h5");
  restart.restart_path = dir / "broken.chk";
  std::ofstream(dir / "broken.chk", std::ios::binary) << good.substr(0, good.size() / 2);  // a full disk cut it
  CHECK_THAT(message_of([&] { run_scene(restart, nullptr); }), Catch::Contains("damaged") && Catch::Contains("cut short"));
  std::string flipped = good;
  flipped[flipped.size() - 3] ^= 0x10;
  std::ofstream(dir / "broken.chk", std::ios::binary) << flipped;
  CHECK_THAT(message_of([&] { run_scene(restart, nullptr); }), Catch::Contains("damaged") && Catch::Contains("checksum"));
  CHECK_FALSE(std::filesystem::exists(dir / "again.h5"));
}

TEST_CASE("an interrupted run restarted without -o continues its own output: the whole run, no row lost", "[unit][run]") {
  const auto dir = testing::scratch_dir("own_restart_continues");
  RunRequest whole = run_request(toy_deck(), dir / "whole", "both");
  whole.t_max_s = 6.0;
  run_scene(whole, nullptr);

  const InterruptHandlers handlers;
  RunRequest first = run_request(toy_deck(), dir / "run", "both");
  first.t_max_s = 6.0;
  first.checkpoint_every_s = 2.0;
  const RunReport stopped = run_scene(first, [](double t, double) {
    if (t >= 3.0 && interrupt_signal() == 0) request_interrupt(SIGTERM);
  });
  REQUIRE(stopped.interrupted_by == SIGTERM);
  const std::size_t rows_before = io::read_channels(dir / "run.h5").rows();
  clear_interrupt();  // a new process would start without it

  RunRequest restart = run_request(toy_deck(), dir / "unused", "both");
  restart.output_base.reset();  // the checkpoint's own output, dir/run
  restart.t_max_s = 6.0;
  restart.restart_path = dir / "run.chk";
  const RunReport report = run_scene(restart, nullptr);
  CHECK(report.outputs.front() == dir / "run.h5");
  for (const char* ext : {".h5", ".out"}) {
    const io::ChannelTable a = io::read_channels(dir / (std::string("whole") + ext));
    const io::ChannelTable b = io::read_channels(dir / (std::string("run") + ext));
    INFO(ext);
    CHECK(b.status == "completed");
    REQUIRE(b.rows() == a.rows());
    CHECK(b.rows() > rows_before);
    CHECK(b.columns == a.columns);  // bit for bit: the copied rows and the ones computed again
  }
  CHECK_FALSE(std::filesystem::exists(dir / "unused.h5"));
}

namespace {

// The riser in a regular wave; `settings` pick the domain and shorten the time domain.
RunRequest riser_request(const std::filesystem::path& base, std::vector<std::string> settings) {
  RunRequest r = run_request(testing::source_dir() / "inputs/slender/riser_harmonic.yaml", base, "out");
  r.deck_settings = std::move(settings);
  return r;
}

}  // namespace

TEST_CASE("a slender run's profile table is owned like the time series: locked, whole, a dead run's kept", "[unit][run]") {
  const auto dir = testing::scratch_dir("own_slender_table");
  const RunRequest r = riser_request(dir / "x", {"analysis.domain=frequency"});
  std::ofstream(dir / "x.amplitude.csv") << "an earlier run's table\n";
  std::ofstream(dir / "x.amplitude.running.csv") << "half the table of a run that was killed\n";
  {
    OutputSet live(dir / "x", "h5");  // another run writing x
    CHECK_THAT(message_of([&] { run_scene(r, nullptr); }), Catch::Contains("being written by another run"));
    CHECK(bytes_of(dir / "x.amplitude.csv") == "an earlier run's table\n");
    CHECK(bytes_of(dir / "x.amplitude.running.csv") == "half the table of a run that was killed\n");
  }
  const RunReport report = run_scene(r, nullptr);
  CHECK(report.outputs == std::vector<std::filesystem::path>{dir / "x.amplitude.csv"});
  CHECK_THAT(bytes_of(dir / "x.amplitude.csv"), Catch::StartsWith("x_m,outer_diameter_m,fd_displacement_m,"));
  CHECK(bytes_of(dir / "x.amplitude.unfinished.csv") == "half the table of a run that was killed\n");
  REQUIRE(report.warnings.size() == 1);
  CHECK_THAT(report.warnings.front(), Catch::Contains("kept as"));
  CHECK_FALSE(std::filesystem::exists(dir / "x.amplitude.running.csv"));
  CHECK_FALSE(std::filesystem::exists(dir / "x.out"));  // no time domain, no time series
  CHECK_FALSE(std::filesystem::exists(dir / "x.lock"));
}

TEST_CASE("a slender run's profile table is written only once the time series is complete", "[unit][run]") {
  // The TD profiles are statistics over the whole window, accumulated step by step: no table, not
  // even under the running name, until the last step (an interrupted run writes none:
  // slender_scene_tests.cpp, the restart case).
  const auto dir = testing::scratch_dir("own_slender_running");
  const RunRequest r = riser_request(dir / "x", {"simulation.t_max_s=40", "analysis.transient_s=10"});
  bool seen = false;
  const RunReport report = run_scene(r, [&](double, double) {
    if (seen) return;
    seen = true;
    CHECK_FALSE(std::filesystem::exists(dir / "x.amplitude.running.csv"));
    CHECK_FALSE(std::filesystem::exists(dir / "x.amplitude.csv"));
  });
  CHECK(seen);
  CHECK(report.outputs == std::vector<std::filesystem::path>{dir / "x.out", dir / "x.amplitude.csv"});
  CHECK(io::read_channels(dir / "x.out").status == "completed");
  CHECK_THAT(bytes_of(dir / "x.amplitude.csv"), Catch::Contains(",td_displacement_m,"));
  CHECK_FALSE(std::filesystem::exists(dir / "x.amplitude.running.csv"));
}
