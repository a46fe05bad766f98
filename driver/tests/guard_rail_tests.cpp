// Guard rails of `fowtsim run`, `turbulence` and `verify` (issue 16): output names, outputs that a
// failed start cannot destroy, interruption by SIGINT/SIGTERM, decks that are not scene decks,
// misspelt channels, and verification that cannot report PASS over nothing.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <thread>

#include <catch2/catch.hpp>
#include <hdf5.h>

#include "run/turbulence_command.hpp"
#include "verify/verify_cases.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/testing/skip.hpp"
#include "run/interrupt.hpp"
#include "run/option_checks.hpp"
#include "run/output_set.hpp"
#include "run/run_scene.hpp"
#include "h5_attributes.hpp"
#include "run_request.hpp"
#include "test_helpers.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

std::filesystem::path toy_deck(const std::filesystem::path& dir, const std::string& extra = "") {
  const auto path = dir / "toy.yaml";
  std::ofstream(path) << "simulation: {t_max_s: 1.0, dt_coupling_s: 0.1}\n" << extra << R"(
toy_oscillators:
  slow: {mass_kg: 1000.0, stiffness_N_m: 1000.0, initial_position_m: 1.0}
  fast: {mass_kg: 10.0, stiffness_N_m: 4000.0, damping_N_s_m: 4.0}
)";
  return path;
}

// The platform-loads scene (a run_fixed_steps scene) on the OC3-Hywind deck, shortened.
std::filesystem::path platform_deck() { return testing::source_dir() / "inputs/oc3_hywind/platform_in_waves.yaml"; }

std::string text_of(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The fowtsim executable built next to this test executable (for exit codes and signals).
std::filesystem::path fowtsim_exe() {
  const auto exe = std::filesystem::read_symlink("/proc/self/exe").parent_path() / "fowtsim";
  if (!std::filesystem::exists(exe)) testing::skip("the fowtsim executable is not built next to the tests: " + exe.string());
  return exe;
}

// Runs `fowtsim args…` with stdout and stderr into `log`; returns the exit status.
int run_fowtsim(const std::string& args, const std::filesystem::path& log) {
  const std::string command = fowtsim_exe().string() + " " + args + " > " + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

// ── item 1, 2: output names ─────────────────────────────────────────────────────────────────

TEST_CASE("output names: the deck file names the default output, -o keeps a given .h5/.out", "[unit][run]") {
  auto resolved = [](const char* deck, std::optional<std::string> o, std::optional<std::string> format) {
    RunRequest r;
    r.deck_path = deck;
    if (o) r.output_base = *o;
    r.output_format = std::move(format);
    return resolve_output_names(r);
  };
  // No -o: runs/<deck file stem>, for a BeamDyn driver too (it used to be the parent folder's name).
  CHECK(*resolved("cases/bd_twist/bd_driver.inp", std::nullopt, std::nullopt).output_base == "runs/bd_driver");
  CHECK(*resolved("inputs/beams/rollup.yaml", std::nullopt, std::nullopt).output_base == "runs/rollup");
  // A .h5/.out extension names the file and, without --out-format, picks the format.
  const RunRequest h5 = resolved("d.yaml", "out/x.h5", std::nullopt);
  CHECK(*h5.output_base == "out/x");
  CHECK(*h5.output_format == "h5");
  const RunRequest out = resolved("d.yaml", "x.out", std::nullopt);
  CHECK(*out.output_base == "x");
  CHECK(*out.output_format == "out");
  CHECK(*resolved("d.yaml", "X.H5", std::nullopt).output_format == "h5");
  // --out-format both: the extension only names the pair.
  const RunRequest both = resolved("d.yaml", "x.h5", std::string("both"));
  CHECK(*both.output_base == "x");
  CHECK(*both.output_format == "both");
  // A matching --out-format is fine, a contradicting one is an input error.
  CHECK(*resolved("d.yaml", "x.out", std::string("out")).output_base == "x");
  CHECK_THROWS_AS(resolved("d.yaml", "x.out", std::string("h5")), InputError);
  CHECK_THAT(message_of([&] { resolved("d.yaml", "x.out", std::string("h5")); }),
             Catch::Contains("-o x.out") && Catch::Contains("--out-format is h5"));
  // Other extensions are part of the name.
  CHECK(*resolved("d.yaml", "x.v2", std::nullopt).output_base == "x.v2");
  CHECK(!resolved("d.yaml", "x.v2", std::nullopt).output_format);
  // The turbulence command's rule: tb, tb.bts and tb.h5 all name the pair tb.bts + tb.h5.
  CHECK(split_known_extension("w/tb.bts", {".bts", ".h5"}).first == "w/tb");
  CHECK(split_known_extension("w/tb.h5", {".bts", ".h5"}).first == "w/tb");
  CHECK(split_known_extension("w/tb", {".bts", ".h5"}).first == "w/tb");
}

TEST_CASE("output names: whole runs write x.h5 for -o x.h5 and x.out for -o x.out, never x.h5.h5", "[unit][run]") {
  const auto dir = testing::scratch_dir("guard_names");
  const auto deck = toy_deck(dir);
  run_scene(run_request(deck, dir / "a.h5", std::nullopt), nullptr);
  CHECK(std::filesystem::exists(dir / "a.h5"));
  CHECK_FALSE(std::filesystem::exists(dir / "a.h5.h5"));
  run_scene(run_request(deck, dir / "b.out", std::nullopt), nullptr);
  CHECK(std::filesystem::exists(dir / "b.out"));
  CHECK_FALSE(std::filesystem::exists(dir / "b.out.h5"));
  CHECK_FALSE(std::filesystem::exists(dir / "b.h5"));
  const RunReport both = run_scene(run_request(deck, dir / "c.h5", std::string("both")), nullptr);
  CHECK(both.outputs == std::vector<std::filesystem::path>{dir / "c.h5", dir / "c.out"});
  CHECK(std::filesystem::exists(dir / "c.h5"));
  CHECK(std::filesystem::exists(dir / "c.out"));
  // No temporary file is left behind.
  for (const auto& e : std::filesystem::directory_iterator(dir))
    CHECK(e.path().filename().string().find(".running") == std::string::npos);
}

TEST_CASE("output names: fowtsim turbulence -o tb.bts writes tb.bts and tb.h5", "[unit][run]") {
  const auto dir = testing::scratch_dir("guard_turbulence");
  const auto deck = dir / "wind.yaml";
  const auto write_wind_deck = [&](double duration_s) {
    std::ofstream(deck) << "wind:\n  model: turbulent\n  speed_m_s: 12.0\n  reference_height_m: 90.0\n"
                        << "  turbulence: {ny: 4, nz: 4, width_m: 40.0, height_m: 40.0, dt_s: 0.5, duration_s: " << duration_s
                        << ", seed: 7}\n";
  };
  write_wind_deck(20.0);
  std::FILE* sink = std::tmpfile();
  CHECK(run_turbulence_command(deck, dir / "tb.bts", sink) == 0);
  std::fclose(sink);
  CHECK(std::filesystem::exists(dir / "tb.bts"));
  CHECK(std::filesystem::exists(dir / "tb.h5"));
  CHECK_FALSE(std::filesystem::exists(dir / "tb.bts.bts"));
  CHECK_FALSE(std::filesystem::exists(dir / "tb.bts.h5"));
  for (const auto& e : std::filesystem::directory_iterator(dir))
    CHECK(e.path().filename().string().find(".running") == std::string::npos);

  // A write that fails (here the HDF5's temporary name is taken by a folder) leaves the field
  // written before untouched (a 40-s field would be twice its size) and no temporary file behind.
  const auto size_before = std::filesystem::file_size(dir / "tb.bts");
  write_wind_deck(40.0);
  std::filesystem::create_directories(dir / "tb.running.h5" / "blocker");
  std::FILE* sink2 = std::tmpfile();
  CHECK_THROWS(run_turbulence_command(deck, dir / "tb", sink2));
  std::fclose(sink2);
  CHECK(std::filesystem::file_size(dir / "tb.bts") == size_before);
  CHECK_FALSE(std::filesystem::exists(dir / "tb.running.bts"));
}

TEST_CASE("output names: a BeamDyn driver input writes runs/bd_driver.h5, not runs/.h5", "[verification][run]") {
  const auto shared = testing::shared_dir_or_skip();
  const auto dir = testing::scratch_dir("guard_beamdyn_name");
  const auto here = std::filesystem::current_path();
  std::filesystem::current_path(dir);  // the default output is relative to the current folder
  RunRequest r;
  r.deck_path = shared / "reference/r-test/modules/beamdyn/bd_static_twisted_with_k1/bd_driver.inp";
  r.beam_segments = 8;
  const RunReport report = run_scene(r, nullptr);
  std::filesystem::current_path(here);
  CHECK(report.outputs == std::vector<std::filesystem::path>{"runs/bd_driver.h5"});
  CHECK(std::filesystem::exists(dir / "runs/bd_driver.h5"));
  CHECK_FALSE(std::filesystem::exists(dir / "runs/.h5"));
}

TEST_CASE("run --dt sets a BeamDyn run's time step, and is refused where the deck sets the steps", "[verification][run]") {
  // The BeamDyn Az00 case over 1 s at its own step, then at twice it: half the rows.
  const auto shared = testing::shared_dir_or_skip();
  const auto dir = testing::scratch_dir("guard_dt");
  RunRequest r = run_request(shared / "reference/r-test/modules/beamdyn/bd_5MW_dynamic_gravity_Az00/bd_driver.inp", dir / "bd");
  r.beam_segments = 8;
  r.t_max_s = 1.0;
  run_scene(r, nullptr);
  const io::ChannelTable fine = io::read_channels(dir / "bd.out");
  const double deck_dt = fine.time()[1] - fine.time()[0];
  r.dt_s = 2.0 * deck_dt;
  run_scene(r, nullptr);
  const io::ChannelTable coarse = io::read_channels(dir / "bd.out");
  CHECK(coarse.rows() == (fine.rows() - 1) / 2 + 1);  // t0 and every step to 1 s
  CHECK(coarse.time()[1] - coarse.time()[0] == Approx(2.0 * deck_dt).epsilon(1e-12));
  RunRequest floating = run_request(platform_deck(), dir / "platform");
  floating.dt_s = 0.01;
  CHECK_THROWS_WITH(run_scene(floating, nullptr), Catch::Contains("--dt") && Catch::Contains("simulation.dt_s"));
  CHECK_FALSE(std::filesystem::exists(dir / "platform.out"));
}

// ── item 3: nothing is created or overwritten before every check passed ───────────────────

TEST_CASE("a failed start leaves an earlier output untouched and a run writes a temporary name", "[unit][run]") {
  const auto dir = testing::scratch_dir("guard_keep");
  RunRequest r = run_request(platform_deck(), dir / "keep", std::string("both"));
  r.t_max_s = 0.5;
  bool seen_running = false;
  run_scene(r, [&](double, double) {
    // While the run goes, the files carry their temporary names only.
    seen_running = std::filesystem::exists(dir / "keep.running.h5") && std::filesystem::exists(dir / "keep.running.out") &&
                   !std::filesystem::exists(dir / "keep.h5");
  });
  CHECK(seen_running);
  REQUIRE(std::filesystem::exists(dir / "keep.h5"));
  CHECK_FALSE(std::filesystem::exists(dir / "keep.running.h5"));
  const std::string good_out = text_of(dir / "keep.out");
  const std::size_t good_rows = io::read_hdf5_channels(dir / "keep.h5").rows();
  CHECK(good_rows == 6);  // t = 0, 0.1, …, 0.5 (dt 0.05, decimation 2)

  // --tmax 0.501: dt 0.05 does not divide it. The error names --tmax; no file is touched.
  r.t_max_s = 0.501;
  const std::string message = message_of([&] { run_scene(r, nullptr); });
  CHECK_THAT(message, Catch::Contains("--tmax 0.501") && Catch::Contains("dt_s"));
  CHECK(io::read_hdf5_channels(dir / "keep.h5").rows() == good_rows);
  CHECK(string_attribute(dir / "keep.h5", "status") == "completed");
  CHECK(text_of(dir / "keep.out") == good_out);
  CHECK_FALSE(std::filesystem::exists(dir / "keep.running.h5"));
  CHECK_FALSE(std::filesystem::exists(dir / "keep.running.out"));

  // An output set that never got a row (the run stopped before it began) removes its temporary
  // files and leaves the final ones as they were.
  {
    OutputSet set(dir / "keep", "both");
    set.begin({ChannelInfo{"X", "m", "x", "test"}}, io::RunMetadata{});
    CHECK(std::filesystem::exists(dir / "keep.running.h5"));
  }
  CHECK_FALSE(std::filesystem::exists(dir / "keep.running.h5"));
  CHECK(string_attribute(dir / "keep.h5", "status") == "completed");

  // An output set dropped mid-run (an exception outside the time loop's handler) keeps its rows
  // under the final name, marked incomplete.
  {
    OutputSet set(dir / "dropped", "h5");
    set.begin({ChannelInfo{"X", "m", "x", "test"}}, io::RunMetadata{});
    const double v = 1.0;
    set.append(0.0, std::span<const double>(&v, 1));
  }
  CHECK(io::read_hdf5_channels(dir / "dropped.h5").rows() == 1);
  CHECK_THAT(string_attribute(dir / "dropped.h5", "status"), Catch::StartsWith("incomplete"));
}

TEST_CASE("a failed run keeps its rows under the final name", "[unit][run]") {
  const auto dir = testing::scratch_dir("guard_failed");
  // Single-rate ΔT = 0.2 s is beyond the fast RK4 limit: the run diverges within a few seconds.
  const auto deck = dir / "deck.yaml";
  std::ofstream(deck) << R"(simulation: {t_max_s: 100.0, dt_coupling_s: 0.2, substeps: 1, coupling: single_rate}
toy_oscillators:
  slow: {mass_kg: 1000.0, stiffness_N_m: 1000.0, initial_position_m: 1.0}
  fast: {mass_kg: 10.0, stiffness_N_m: 4000.0, damping_N_s_m: 4.0}
)";
  CHECK_THROWS_AS(run_scene(run_request(deck, dir / "run.h5", std::nullopt), nullptr), NumericalError);
  CHECK(io::read_hdf5_channels(dir / "run.h5").rows() > 1);
  CHECK_THAT(string_attribute(dir / "run.h5", "status"), Catch::StartsWith("failed"));
  CHECK_FALSE(std::filesystem::exists(dir / "run.running.h5"));
}

// ── item 4: SIGINT / SIGTERM ──────────────────────────────────────────────────────────────

TEST_CASE("SIGINT stops a run at the end of the step: rows flushed, status interrupted, summary", "[unit][run]") {
  const auto dir = testing::scratch_dir("guard_sigint");
  const InterruptHandlers handlers;
  RunRequest r = run_request(platform_deck(), dir / "run", std::string("h5"));
  r.t_max_s = 600.0;
  double raised_at = -1;
  const RunReport report = run_scene(r, [&](double t, double) {
    if (t >= 0.5 && raised_at < 0) {
      raised_at = t;
      std::raise(SIGINT);  // the handler only sets the flag; the loop stops after this step
    }
  });
  CHECK(report.interrupted_by == SIGINT);
  CHECK(report.simulated_s == Approx(raised_at));
  CHECK(report.t_max_s == 600.0);
  CHECK(interrupted_exit_code(report.interrupted_by) == 130);
  CHECK(interrupted_exit_code(SIGTERM) == 143);
  const auto h5 = dir / "run.h5";
  CHECK_THAT(string_attribute(h5, "status"), Catch::StartsWith("interrupted at t = 0.5 s") && Catch::Contains("SIGINT"));
  CHECK(double_attribute(h5, "end_time_s") == Approx(raised_at));
  CHECK(double_attribute(h5, "wall_time_s") >= 0.0);
  const io::ChannelTable table = io::read_hdf5_channels(h5);
  CHECK(table.time().back() == Approx(raised_at));  // decimation 2: 0, 0.1, …, 0.5
  CHECK(table.rows() == 6);

  std::FILE* out = std::tmpfile();
  print_run_summary(out, report);
  std::rewind(out);
  std::string summary(4096, '\0');
  summary.resize(std::fread(summary.data(), 1, summary.size(), out));
  std::fclose(out);
  CHECK_THAT(summary, Catch::Contains("interrupted at t = 0.5 s of 600 s (SIGINT)"));
}

TEST_CASE("SIGTERM from another thread stops a run the same way", "[unit][run]") {
  const auto dir = testing::scratch_dir("guard_sigterm");
  const InterruptHandlers handlers;
  RunRequest r = run_request(platform_deck(), dir / "run", std::string("h5"));
  r.t_max_s = 600.0;
  std::atomic<bool> started{false};
  std::thread killer([&] {
    while (!started) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    kill(getpid(), SIGTERM);
  });
  const RunReport report = run_scene(r, [&](double, double) {
    started = true;
    // Hold the first steps until the signal is in, so that it arrives mid-run on any machine.
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (interrupt_signal() == 0 && std::chrono::steady_clock::now() < until) std::this_thread::yield();
  });
  killer.join();
  CHECK(report.interrupted_by == SIGTERM);
  CHECK(report.simulated_s < 600.0);
  CHECK_THAT(string_attribute(dir / "run.h5", "status"), Catch::Contains("SIGTERM"));
  CHECK(double_attribute(dir / "run.h5", "end_time_s") == Approx(report.simulated_s));
}

TEST_CASE("SIGINT stops the BeamDyn time loop too", "[verification][run]") {
  const auto shared = testing::shared_dir_or_skip();
  const auto dir = testing::scratch_dir("guard_sigint_beamdyn");
  const InterruptHandlers handlers;
  RunRequest r = run_request(shared / "reference/r-test/modules/beamdyn/bd_5MW_dynamic_gravity_Az00/bd_driver.inp",
                             dir / "run", std::string("h5"));
  r.beam_segments = 8;
  int calls = 0;
  const RunReport report = run_scene(r, [&](double, double) {
    if (++calls == 3) std::raise(SIGINT);
  });
  CHECK(report.interrupted_by == SIGINT);
  CHECK(report.large_steps == 3);
  CHECK_THAT(string_attribute(dir / "run.h5", "status"), Catch::StartsWith("interrupted at t = "));
  CHECK(io::read_hdf5_channels(dir / "run.h5").rows() == 4);
}

TEST_CASE("SIGINT stops the toy scene (the common time loop) after the step", "[unit][run]") {
  const auto dir = testing::scratch_dir("guard_sigint_toy");
  const InterruptHandlers handlers;
  int calls = 0;
  const RunReport report = run_scene(run_request(toy_deck(dir), dir / "run", std::string("h5")), [&](double, double) {
    if (++calls == 3) std::raise(SIGINT);
  });
  clear_interrupt();  // the flag outlives the handlers: later runs in this process must not stop
  CHECK(report.interrupted_by == SIGINT);
  CHECK(report.large_steps == 3);
  CHECK(report.t_max_s == 1.0);
  CHECK_THAT(string_attribute(dir / "run.h5", "status"), Catch::StartsWith("interrupted at t = 0.3 s") && Catch::Contains("SIGINT"));
  CHECK(io::read_hdf5_channels(dir / "run.h5").time() == std::vector<double>{0.0, 0.1, 2 * 0.1, 3 * 0.1});
}

TEST_CASE("fowtsim run exits 130 on SIGINT with the summary printed", "[unit][run]") {
  const auto dir = testing::scratch_dir("guard_sigint_exe");
  const auto exe = fowtsim_exe();
  const auto log = dir / "log.txt";
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    std::freopen(log.c_str(), "w", stdout);
    std::freopen(log.c_str(), "a", stderr);
    execl(exe.c_str(), "fowtsim", "run", platform_deck().c_str(), "-o", (dir / "run.h5").c_str(), "--tmax", "100000",
          static_cast<char*>(nullptr));
    std::_Exit(127);
  }
  // Signal once the run is writing (its temporary file exists), then wait for it.
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(4);
  while (!std::filesystem::exists(dir / "run.running.h5") && std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 130);
  CHECK_THAT(text_of(log), Catch::Contains("fowtsim run summary") && Catch::Contains("interrupted at t = "));
  CHECK_THAT(string_attribute(dir / "run.h5", "status"), Catch::StartsWith("interrupted at t = "));
}

// ── item 5: guard rails ───────────────────────────────────────────────────────────────────

TEST_CASE("OpenFAST and TurbSim inputs are named as such, not reported as YAML errors", "[unit][run]") {
  const auto dir = testing::scratch_dir("guard_openfast");
  auto expect_openfast = [&](const std::string& name, const std::string& text) {
    const auto path = dir / name;
    std::ofstream(path) << text;
    INFO(name);
    CHECK_THAT(message_of([&] { run_scene(run_request(path, dir / "run", std::nullopt), nullptr); }),
               Catch::Contains("OpenFAST/TurbSim input is not read by fowtsim run"));
    CHECK_FALSE(std::filesystem::exists(dir / "run.out"));
  };
  expect_openfast("case.fst", "------- OpenFAST EXAMPLE INPUT FILE -------\nFAST Certification Test\n"
                              "---------------------- SIMULATION CONTROL ----\nFalse  Echo  - Echo input data\n");
  expect_openfast("TurbSim.inp", "---------TurbSim v2.00.* Input File------------------------\nfor Certification Test\n"
                                 "---------Runtime Options-----------------------------------\n2318573  RandSeed1\n");
  expect_openfast("ElastoDyn.dat", "------- ELASTODYN INPUT FILE -------\nNREL 5.0 MW\n");
  // Without a telling extension, the banner line gives it away; and a file that is no YAML at all.
  expect_openfast("case.txt", "------- HydroDyn Input File -------\nNREL 5.0 MW offshore\n");
  expect_openfast("notes.cfg", "key: [unclosed\n  : : :\n");
}

TEST_CASE("an empty or component deck says which top-level keys make a scene", "[unit][run]") {
  const auto dir = testing::scratch_dir("guard_component");
  const auto empty = dir / "empty.yaml";
  std::ofstream(empty) << "# nothing yet\n";
  const std::string empty_message = message_of([&] { run_scene(run_request(empty, dir / "run", std::nullopt), nullptr); });
  CHECK_THAT(empty_message, Catch::Contains("no scene to run") && Catch::Contains("it is empty"));
  for (const char* key : {"structure", "platform_motion", "beam", "toy_oscillators"}) CHECK_THAT(empty_message, Catch::Contains(key));

  const auto hydro = testing::source_dir() / "inputs/oc3_hywind/hydro.yaml";
  const std::string hydro_message = message_of([&] { run_scene(run_request(hydro, dir / "run", std::nullopt), nullptr); });
  CHECK_THAT(hydro_message, Catch::Contains("no scene to run") && Catch::Contains("top-level keys are hydro") &&
                                Catch::Contains("structure") && Catch::Contains("include"));
  CHECK_FALSE(std::filesystem::exists(dir / "run.out"));

  // A misspelt scene key gets a "did you mean".
  const auto typo = dir / "typo.yaml";
  std::ofstream(typo) << "toy_oscilators: {}\n";
  CHECK_THAT(message_of([&] { run_scene(run_request(typo, dir / "run", std::nullopt), nullptr); }),
             Catch::Contains("did you mean `toy_oscillators`?"));
}

TEST_CASE("a misspelt output channel gets a did-you-mean", "[unit][run]") {
  const auto dir = testing::scratch_dir("guard_channel");
  const auto deck = toy_deck(dir, "output: {channels: [ToySlowPos, toyslowvell]}\n");
  const std::string message = message_of([&] { run_scene(run_request(deck, dir / "run", std::nullopt), nullptr); });
  CHECK_THAT(message, Catch::Contains("output.channels[1]") && Catch::Contains("unknown channel 'toyslowvell'") &&
                          Catch::Contains("did you mean `ToySlowVel`?"));
  // Far from every name: no guess, the list of names instead.
  const auto far = toy_deck(dir, "output: {channels: [PtfmSurge]}\n");
  const std::string far_message = message_of([&] { run_scene(run_request(far, dir / "run", std::nullopt), nullptr); });
  CHECK_THAT(far_message, !Catch::Contains("did you mean") && Catch::Contains("available: ToySlowPos"));
}

TEST_CASE("every output channel the scene does not write is listed at once, each with why", "[unit][run]") {
  // The platform scene writes the mooring tensions as FAIRTENi (MoorDyn's names).
  const auto dir = testing::scratch_dir("guard_channels_all");
  std::ofstream(dir / "deck.yaml") << "include: [" << platform_deck().string() << "]\n"
                                   << "output: {channels: [HydroFxi, 'T[1]', TTDspFA, HydroFxii, Zebra]}\n";
  const std::string message = message_of([&] { run_scene(run_request(dir / "deck.yaml", dir / "run"), nullptr); });
  CHECK_THAT(message, Catch::Contains("names 4 channels this scene does not write"));
  CHECK_THAT(message, Catch::Contains("output.channels[1]: unknown channel 'T[1]'") && Catch::Contains("did you mean `FAIRTEN1`?"));
  CHECK_THAT(message, Catch::Contains("output.channels[2]: unknown channel 'TTDspFA'") && Catch::Contains("flexible tower"));
  CHECK_THAT(message, Catch::Contains("output.channels[3]: unknown channel 'HydroFxii'") && Catch::Contains("did you mean `HydroFxi`?"));
  CHECK_THAT(message, Catch::Contains("output.channels[4]: unknown channel 'Zebra': not a channel of this scene"));
  CHECK_THAT(message, !Catch::Contains("output.channels[0]"));
}

TEST_CASE("a mooring solver setting outside the module's range stops at its deck line", "[unit][run]") {
  // One range per key: the deck reader holds the mooring module's own bounds (60 … 10000).
  const auto dir = testing::scratch_dir("guard_mooring_range");
  std::ofstream(dir / "deck.yaml") << "include: [" << (testing::source_dir() / "inputs/oc3_hywind/free_decay_surge.yaml").string()
                                   << "]\nmooring:\n  solver: {max_bisection_iterations: 30}\n";
  const std::string message = message_of([&] { run_scene(run_request(dir / "deck.yaml", dir / "run", std::nullopt), nullptr); });
  CHECK_THAT(message, Catch::Contains("deck.yaml:3") && Catch::Contains("max_bisection_iterations") && Catch::Contains("60"));
  CHECK_FALSE(std::filesystem::exists(dir / "run.h5"));
}

TEST_CASE("tmax abc on the command line says a positive number is wanted", "[unit][run]") {
  CHECK(positive_number_problem("60", "a positive number of seconds").empty());
  CHECK(positive_number_problem("1e-3", "a positive number of seconds").empty());
  CHECK(positive_number_problem("abc", "a positive number of seconds") == "expected a positive number of seconds, found 'abc'");
  CHECK_FALSE(positive_number_problem("-1", "x").empty());
  CHECK_FALSE(positive_number_problem("0", "x").empty());
  CHECK_FALSE(positive_number_problem("5s", "x").empty());
  CHECK_FALSE(positive_number_problem("nan", "x").empty());
  // Through the command line: exit 2 and the message.
  const auto dir = testing::scratch_dir("guard_tmax");
  const auto log = dir / "log.txt";
  CHECK(run_fowtsim("run " + platform_deck().string() + " --tmax abc", log) == 2);
  CHECK_THAT(text_of(log), Catch::Contains("--tmax") && Catch::Contains("a positive number"));
}

TEST_CASE("tools/run applies options without a deck to the default deck", "[unit][run]") {
  // tools/run with its set-up replaced by a stub and fowtsim by a script that prints its arguments.
  const auto dir = testing::scratch_dir("guard_tools_run");
  std::filesystem::create_directories(dir / "tools/lib");
  std::filesystem::create_directories(dir / "build/driver");
  std::filesystem::copy_file(testing::source_dir() / "tools/run", dir / "tools/run");
  std::ofstream(dir / "tools/lib/setup.sh") << "FOWTSIM_ROOT=" << dir.string() << "\n";
  std::ofstream(dir / "build/driver/fowtsim") << "#!/bin/sh\necho \"$@\"\n";
  std::filesystem::permissions(dir / "build/driver/fowtsim", std::filesystem::perms::owner_all, std::filesystem::perm_options::add);
  auto args_of = [&](const std::string& args) {
    const std::string command = "bash " + (dir / "tools/run").string() + " " + args + " > " + (dir / "args.txt").string();
    REQUIRE(std::system(command.c_str()) == 0);
    std::string text = text_of(dir / "args.txt");
    while (!text.empty() && text.back() == '\n') text.pop_back();
    return text;
  };
  const std::string default_deck = (dir / "inputs/oc3_hywind/turbine_flexible_ntm_12mps_irregular.yaml").string();
  CHECK(args_of("--tmax 60") == "run " + default_deck + " --tmax 60");
  CHECK(args_of("") == "run " + default_deck);
  CHECK(args_of("my.yaml --tmax 60") == "run my.yaml --tmax 60");
  CHECK(args_of("-o x.h5") == "run " + default_deck + " -o x.h5");
}

// ── item 6: verify ────────────────────────────────────────────────────────────────────────

TEST_CASE("verify: the shared folder is found next to the repository, whatever the current folder", "[unit][verify]") {
  const auto here = std::filesystem::current_path();
  std::filesystem::current_path(std::filesystem::temp_directory_path());
  const std::filesystem::path from_tmp = default_shared_dir();
  std::filesystem::current_path(here);
  CHECK(from_tmp == default_shared_dir());
  CHECK(from_tmp.is_absolute());
  CHECK(std::filesystem::exists(source_root() / "inputs/oc3_hywind/hydro.yaml"));
  CHECK(from_tmp == (source_root().parent_path() / "shared").lexically_normal());
  CHECK(std::filesystem::equivalent(source_root(), testing::source_dir()));
}

TEST_CASE("verify: a case without reference data is SKIPPED and nothing run is not a PASS", "[unit][verify]") {
  const auto dir = testing::scratch_dir("guard_verify");
  std::FILE* out = std::tmpfile();
  const VerificationOutcome outcome = run_verification({"beam-frequencies"}, dir / "nowhere", out);
  CHECK(outcome.rows.empty());
  REQUIRE(outcome.skipped.size() == 1);
  CHECK(outcome.skipped[0].case_name == "beam-frequencies");
  CHECK_THAT(outcome.skipped[0].reason, Catch::Contains("reference data not found") && Catch::Contains("nowhere"));
  CHECK(outcome.exit_code() != 0);
  print_verification_outcome(out, outcome);
  std::rewind(out);
  std::string text(16384, '\0');
  text.resize(std::fread(text.data(), 1, text.size(), out));
  std::fclose(out);
  CHECK_THAT(text, Catch::Contains("beam-frequencies SKIPPED: reference data not found") &&
                       Catch::Contains("no verification check ran") && !Catch::Contains("PASS"));

  // Some checks ran and passed, one case skipped: PASS, with the skip said.
  VerificationOutcome mixed;
  mixed.rows.push_back({"coupling", "metric", 1.0, "< 2", "analytic", true});
  mixed.skipped.push_back({"beam-beamdyn", "reference data not found under x"});
  CHECK(mixed.exit_code() == 0);
  mixed.rows.push_back({"coupling", "metric 2", 3.0, "< 2", "analytic", false});
  CHECK(mixed.exit_code() == 1);
}

TEST_CASE("fowtsim turbulence on a turbine deck uses its wind section", "[unit][run]") {
  const auto dir = testing::scratch_dir("guard_turbulence_turbine");
  const auto turbine = testing::source_dir() / "inputs/oc3_hywind/free_decay_pitch.yaml";
  std::ofstream(dir / "turbine.yaml") << "include: [" << turbine.string() << "]\n"
                                      << "wind: {model: turbulent, speed_m_s: 12.0, reference_height_m: 90.0,\n"
                                      << "  turbulence: {ny: 4, nz: 4, width_m: 40.0, height_m: 40.0, dt_s: 0.5, duration_s: 20.0, seed: 7}}\n";
  std::FILE* sink = std::tmpfile();
  CHECK(run_turbulence_command(dir / "turbine.yaml", dir / "tb", sink) == 0);
  CHECK(std::filesystem::exists(dir / "tb.bts"));
  // A deck without a wind section says what is missing.
  CHECK_THROWS_AS(run_turbulence_command(turbine, dir / "none", sink), InputError);
  std::fclose(sink);
}
