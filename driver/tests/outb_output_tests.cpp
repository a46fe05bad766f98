// `-o x.outb` / `--out-format outb` (issue 23): the run writes OpenFAST's binary output, holding the
// same numbers as its HDF5, and a restart continues an interrupted .outb like the other formats.
#include <signal.h>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/testing/skip.hpp"
#include "run/interrupt.hpp"
#include "run/output_set.hpp"
#include "run/run_scene.hpp"
#include "run_request.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

std::filesystem::path toy_deck() { return testing::source_dir() / "inputs/toy_coupled_oscillators.yaml"; }

// Channels bit for bit; time to rounding (the .outb keeps the first time and the interval).
void check_same_run(const io::ChannelTable& outb, const io::ChannelTable& h5) {
  REQUIRE(outb.rows() == h5.rows());
  REQUIRE(outb.columns.size() == h5.columns.size());
  for (std::size_t c = 1; c < h5.columns.size(); ++c) {
    INFO(h5.names[c]);
    CHECK(outb.names[c] == h5.names[c].substr(0, 10));
    CHECK(outb.columns[c] == h5.columns[c]);
  }
  for (std::size_t i = 0; i < h5.rows(); ++i)
    if (std::abs(outb.time()[i] - h5.time()[i]) > 1e-12 * (1.0 + h5.time()[i])) FAIL("time of row " << i);
}

}  // namespace

TEST_CASE("outb output names: -o x.outb picks the format; with --out-format both it is an error", "[unit][run]") {
  RunRequest r;
  r.deck_path = "d.yaml";
  r.output_base = "out/x.outb";
  const RunRequest picked = resolve_output_names(r);
  CHECK(*picked.output_base == "out/x");
  CHECK(*picked.output_format == "outb");
  r.output_format = "both";  // both is .h5 and .out
  CHECK_THROWS_AS(resolve_output_names(r), InputError);
  r.output_base = "x.h5";
  r.output_format = "outb";
  CHECK_THROWS_AS(resolve_output_names(r), InputError);
}

TEST_CASE("a run with -o x.outb writes x.outb holding the HDF5's numbers, and says which names it cut", "[unit][run]") {
  const auto dir = testing::scratch_dir("outb_run");
  RunRequest h5 = run_request(toy_deck(), dir / "ref", "h5");
  h5.t_max_s = 4.0;
  run_scene(h5, nullptr);
  RunRequest outb = run_request(toy_deck(), dir / "run.outb", std::nullopt);
  outb.t_max_s = 4.0;
  const RunReport report = run_scene(outb, nullptr);
  CHECK(report.outputs == std::vector<std::filesystem::path>{dir / "run.outb"});
  CHECK_FALSE(std::filesystem::exists(dir / "run.outb.h5"));
  const io::ChannelTable table = io::read_channels(dir / "run.outb");
  CHECK(table.status == "completed");
  CHECK(table.warnings.empty());
  check_same_run(table, io::read_channels(dir / "ref.h5"));
  // The toy's long names (ToyExactSlowPos, …) do not fit the format's 10 characters: the summary says so.
  bool noted = false;
  for (const std::string& w : report.warnings) noted = noted || w.find("ToyExactSlowPos → ToyExactSl") != std::string::npos;
  CHECK(noted);
}

TEST_CASE("an interrupted .outb run restarted from its checkpoint continues its own .outb", "[unit][run]") {
  const auto dir = testing::scratch_dir("outb_restart");
  RunRequest whole = run_request(toy_deck(), dir / "whole", "h5");
  whole.t_max_s = 6.0;
  run_scene(whole, nullptr);

  const InterruptHandlers handlers;
  RunRequest first = run_request(toy_deck(), dir / "run", "outb");
  first.t_max_s = 6.0;
  first.checkpoint_every_s = 2.0;
  const RunReport stopped = run_scene(first, [](double t, double) {
    if (t >= 3.0 && interrupt_signal() == 0) request_interrupt(SIGTERM);
  });
  REQUIRE(stopped.interrupted_by == SIGTERM);
  CHECK_THAT(io::read_channels(dir / "run.outb").status, Catch::StartsWith("interrupted at t = "));
  clear_interrupt();

  RunRequest restart = run_request(toy_deck(), dir / "unused", "outb");
  restart.output_base.reset();  // the checkpoint's own output, dir/run
  restart.t_max_s = 6.0;
  restart.restart_path = dir / "run.chk";
  const RunReport report = run_scene(restart, nullptr);
  CHECK(report.outputs.front() == dir / "run.outb");
  const io::ChannelTable continued = io::read_channels(dir / "run.outb");
  CHECK(continued.status == "completed");
  check_same_run(continued, io::read_channels(dir / "whole.h5"));
}
