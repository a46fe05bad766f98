// fowtsim: the command line. The only place that prints and chooses exit codes:
//   0 success · 1 a comparison or verification failed · 2 bad input or usage · 3 numerical failure
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli/progress_bar.hpp"
#include "verify/reports.hpp"
#include "verify/verify_cases.hpp"
#include "compare/channel_compare.hpp"
#include "compare/comparison_table.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/core/version.hpp"
#include "fowtsim/io/readers.hpp"
#include "run/interrupt.hpp"
#include "run/option_checks.hpp"
#include "run/run_scene.hpp"
#include "run/turbulence_command.hpp"
#include "cli/modes_command.hpp"
#include "cli/screen_command.hpp"
#include "cli/post_command.hpp"
#include "cli/post_config.hpp"
#include "cli/sweep_command.hpp"
#include "sweep/sweep_spec.hpp"
#include "decks/wind_deck.hpp"
#include "scenes/beam_scene.hpp"
#include "scenes/floating_scene.hpp"
#include "scenes/platform_scene.hpp"
#include "scenes/slender_scene.hpp"
#include "scenes/toy_scene.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

constexpr int kExitFail = 1, kExitInput = 2, kExitNumerical = 3;

// SIGINT/SIGTERM/SIGHUP stop the run at the end of the current step; the files are closed as
// "interrupted at t = …", the summary is printed and the exit code is 128 + signal (130, 143, 129).
int run_command(const RunRequest& request) {
  const InterruptHandlers handlers;
  ProgressBar bar(stdout);
  const RunReport report = run_scene(request, [&](double t, double t_max) { bar.update(t, t_max); });
  bar.done();
  print_run_summary(stdout, report);
  return report.interrupted_by ? interrupted_exit_code(report.interrupted_by) : 0;
}

// "--tmax abc" or "--tmax -1": say what is wanted, not CLI11's conversion message.
CLI::Validator positive(const char* what) {
  return CLI::Validator([what](std::string& text) { return positive_number_problem(text, what); }, "");
}

int compare_command(const std::string& ref, const std::string& test, const std::vector<std::string>& channels,
                    std::optional<double> rtol, std::optional<double> atol, const std::string& tolerance_file,
                    const std::vector<double>& window, bool stats, double stats_percent,
                    std::optional<double> wohler_exponent) {
  CompareOptions options = tolerance_file.empty() ? CompareOptions{} : load_tolerance_file(tolerance_file);
  if (rtol || atol) options.default_tolerance = {rtol.value_or(0.0), atol.value_or(0.0), 0.0};
  if (window.size() == 2) options.window = std::pair(window[0], window[1]);
  options.statistics = stats;
  options.statistics_percent = stats_percent;
  options.wohler_exponent = wohler_exponent;
  if (!channels.empty()) options.channels = channels;
  const io::ChannelTable reference = io::read_channels(ref), tested = io::read_channels(test);
  for (const auto& [table, name] : {std::pair(&reference, ref), std::pair(&tested, test)})
    for (const std::string& warning : io::reading_warnings(*table, name)) fmt::print(stderr, "warning: {}\n", warning);
  const ComparisonReport report = compare_tables(reference, tested, options);
  print_comparison(stdout, report);
  return report.pass() ? 0 : kExitFail;
}

// A case without its reference data is SKIPPED with the reason; nothing verified is a failure.
int verify_command(const std::vector<std::string>& cases, const std::filesystem::path& shared_dir) {
  const VerificationOutcome outcome = run_verification(cases, shared_dir, stdout);
  print_verification_outcome(stdout, outcome);
  return outcome.exit_code() == 0 ? 0 : kExitFail;
}

// What a benchmark case costs on one core of this machine kind, said before anything runs.
std::string expected_duration(const std::string& name) {
  if (name == "beam") return "about 15 minutes (its ARKODE 49-volume case alone takes 12)";
  if (name == "turbine") return "about 5 minutes (84 runs of the coupled OC3 load case)";
  if (name == "stability") return "about 4 minutes (60 runs of 120 s of the default deck on the rigid tower, 6 of 600 s on the flexible one)";
  if (name == "riser") return "about 20 seconds (the four riser cases and a time-step study)";
  if (name == "startup") return "about 15 seconds (twice 600 s of the land-based turbine, seed 002 Sec. 5.6)";
  if (name == "options") return "about 5 minutes (26 runs of the 600-s OC3 load case: rigid, Rayleigh-Ritz and MBBT blades, the default deck as a user runs it)";
  return "under a minute";
}

int bench_command(std::vector<std::string> cases) {
  if (cases.empty() || (cases.size() == 1 && cases[0] == "all")) cases = benchmark_case_names();
  fmt::print("fowtsim bench: {} case{}\n", cases.size(), cases.size() == 1 ? "" : "s");
  for (const std::string& name : cases) fmt::print("  {:<10} {}\n", name, expected_duration(name));
  for (std::size_t i = 0; i < cases.size(); ++i) {
    fmt::print("\n[{}/{}] {} …\n", i + 1, cases.size(), cases[i]);
    std::fflush(stdout);
    const auto start = std::chrono::steady_clock::now();
    run_benchmark_case(cases[i], stdout);
    fmt::print("[{}/{}] {} done in {:.1f} s\n", i + 1, cases.size(), cases[i],
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"fowtsim — time-domain aero-hydro-servo-elastic simulation of floating offshore wind turbines"};
  app.set_version_flag("--version", std::string("fowtsim ") + kVersion);
  app.require_subcommand(0, 1);
  bool help_deck = false;
  app.add_flag("--help-deck", help_deck, "print every deck key with type, unit, range and default");

  RunRequest request;
  std::string out_base, out_format;
  double tmax = 0;
  auto* run = app.add_subcommand("run", "run a scene deck");
  run->add_option("deck", request.deck_path, "scene deck (YAML), or a BeamDyn driver input (bd_driver.inp)")
      ->required()
      ->check(CLI::ExistingFile);
  run->add_option("-o,--output", out_base,
                  "output path (default runs/<deck file name without extension>). -o x.h5 writes x.h5, -o x.out "
                  "x.out and -o x.outb x.outb (the extension picks the format over the deck's output.format); without one the "
                  "format's extension is appended (-o x → x.h5). With --out-format both, a given .h5/.out only names "
                  "the pair: -o x.h5 writes x.h5 and x.out. An extension that contradicts --out-format is an "
                  "error. Files are written as <name>.running.<ext> and renamed when the run ends");
  run->add_option("--out-format", out_format, "output format")->check(CLI::IsMember({"h5", "out", "outb", "both"}));
  run->add_option("--set", request.deck_settings,
                  "set a deck key over the deck and its includes, e.g. --set wind.speed_m_s=14 (repeatable; the value "
                  "is YAML: a number, a word, [a, b] or {k: v}; the deck hash, and so checkpoints, record the settings)")
      ->allow_extra_args(false);  // one value per --set: the deck after it stays the deck
  run->add_option("--tmax", tmax, "simulated time [s], overrides simulation.t_max_s")
      ->check(positive("a positive number of seconds"));
  double dt = 0;
  run->add_option("--dt", dt, "beam time step [s] of a BeamDyn driver input or a beam deck, overrides its DT / simulation.dt_s")
      ->check(positive("a positive number of seconds"));
  int segments = 0;
  std::string integrator;
  run->add_option("--segments", segments, "finite volumes per beam (BeamDyn cases; default 48)")->check(positive("a positive whole number"));
  run->add_option("--integrator", integrator, "beam step integrator")->check(CLI::IsMember({"generalized_alpha", "erk"}));
  int matrix_age = 0;
  run->add_option("--matrix-age", matrix_age,
                  "generalized-α: rebuild the beam step matrix at least every N steps (1 = every step, "
                  "the seed's scheme; default 20)")
      ->check(positive("a positive whole number"));
  double checkpoint_every = 0;
  std::string restart;
  run->add_option("--checkpoint-every", checkpoint_every,
                  "write the scene's whole state to <output>.chk every T seconds (floating turbine, toy oscillators, slender body)")
      ->check(positive("a positive number of seconds"));
  std::string turbulence_cache;
  run->add_option("--turbulence-cache", turbulence_cache,
                  "read a generated turbulence field from this folder when a run with the same wind stored it there, else "
                  "generate and store it (what `fowtsim sweep` gives cases that share a wind seed)");
  run->add_option("--restart", restart,
                  "continue bit-identically from a checkpoint of the same deck; the output starts at its time")
      ->check(CLI::ExistingFile);

  std::string ref, test, tolerance_file;
  std::vector<std::string> channels;
  double rtol = 0, atol = 0;
  auto* compare = app.add_subcommand("compare", "compare the channels of two output files (.h5, .out, .outb)");
  compare->add_option("reference", ref, "reference output")->required()->check(CLI::ExistingFile);
  compare->add_option("test", test, "output to check")->required()->check(CLI::ExistingFile);
  compare->add_option("--channels", channels, "channels to compare (default: all common)")->delimiter(',');
  auto* rtol_opt = compare->add_option("--rtol", rtol,
                                       "relative tolerance (default: 1e-3 of the value plus 1e-3 of the channel's range; "
                                       "with --rtol/--atol: |test − ref| ≤ atol + rtol·|ref|)")
                      ->check(CLI::NonNegativeNumber);
  auto* atol_opt = compare->add_option("--atol", atol, "absolute tolerance, channel unit (default 0 with --rtol)")->check(CLI::NonNegativeNumber);
  std::vector<double> window;
  compare->add_option("--window", window, "compare only over T0 T1 [s] (skip start-up transients)")->expected(2);
  bool stats = false;
  auto* stats_flag = compare->add_flag("--stats", stats,
                                       "compare each channel's mean and std instead of sample by sample: for runs that "
                                       "cannot agree sample by sample (other seeds, other models)");
  double stats_percent = kStatisticsPercent;
  compare->add_option("--stats-percent", stats_percent,
                      "with --stats: the largest difference that passes, in % of the mean's scale max(|mean|, std) "
                      "and of the std (default 5: just above what the OC3 load case measures against OpenFAST)")
      ->check(positive("a positive percentage"))
      ->needs(stats_flag);
  stats_flag->excludes(rtol_opt)->excludes(atol_opt);
  double wohler = 0;
  compare->add_option("--wohler", wohler,
                      "with --stats: also compare each channel's damage-equivalent load of this Wöhler exponent "
                      "(MLife: rainflow, f_eq 1 Hz over the window, no Goodman)")
      ->check(positive("a positive Wöhler exponent"))
      ->needs(stats_flag);
  auto* tol_opt = compare->add_option("--tolerances", tolerance_file, "per-channel tolerance file (YAML)")->check(CLI::ExistingFile);
  tol_opt->excludes(rtol_opt)->excludes(atol_opt);

  std::vector<std::string> cases;
  auto* verify = app.add_subcommand("verify", "run verification cases against analytic or published answers");
  verify->add_option("cases", cases,
                     "cases (default all): coupling, beam-rollup, beam-curved, beam-timestep, beam-beamdyn, beam-frequencies, pipe, sea, "
                     "aero, wind, multibody, control, flexbody, slender, free-decay, turbine-validation, turbine-oc3");
  std::string shared_dir = default_shared_dir().string();
  verify->add_option("--shared", shared_dir,
                     "directory holding reference/ (default ../shared next to the repository: " + shared_dir + ")");
  std::vector<std::string> bench_cases;
  auto* bench = app.add_subcommand("bench", "benchmark run time against error");
  bench->add_option("cases", bench_cases, "cases (default all): coupling, beam, hydro, waves, aero, multibody, startup, options, turbine, stability, riser, slender");
  bench->add_option("--shared", shared_dir, "directory holding reference/ (default " + shared_dir + ")");

  std::string wind_deck, wind_out;
  std::string modes_deck, modes_output;
  std::vector<std::string> modes_settings;
  auto* modes = app.add_subcommand("modes", "natural frequencies, damping and mode shapes of a floating-turbine deck, "
                                            "linearised about its initial state (tower and blades at their static deflection)");
  modes->add_option("deck", modes_deck, "floating-turbine deck (rigid or Rayleigh-Ritz blades)")->required()->check(CLI::ExistingFile);
  modes->add_option("--set", modes_settings, "set a deck key, as for run")->allow_extra_args(false);
  modes->add_option("-o,--output", modes_output, "also write the frequencies, damping and shapes to OUT.h5 or OUT.csv");
  std::string screen_deck, screen_output;
  std::vector<std::string> screen_settings;
  auto* screen = app.add_subcommand("screen", "frequency-domain screening of a floating-turbine deck: operating point, coupled "
                                              "modes, RAOs, PSDs and standard deviations in its waves and turbulence");
  screen->add_option("deck", screen_deck, "floating-turbine deck (rigid blades)")->required()->check(CLI::ExistingFile);
  screen->add_option("--set", screen_settings, "set a deck key, as for run")->allow_extra_args(false);
  screen->add_option("-o,--output", screen_output, "also write the RAOs, PSDs and statistics to OUT.h5");
  auto* turbulence = app.add_subcommand("turbulence", "generate a turbulent wind field (IEC Kaimal) to .bts and .h5");
  turbulence->add_option("deck", wind_deck, "deck with a `wind:` section of model turbulent")->required()->check(CLI::ExistingFile);
  turbulence->add_option("-o,--output", wind_out,
                         "output path: writes BASE.bts and BASE.h5; a given .bts or .h5 extension is replaced, not "
                         "appended (-o tb.bts → tb.bts, tb.h5; default runs/<deck name>)");

  PostOptions post_options;
  std::vector<std::string> post_files, post_outputs;
  std::vector<double> post_window;
  std::string del_config, residue = "half", plot_dir, lifetime_spec;
  auto* post_command = app.add_subcommand("post", "statistics, DELs, spectra and proper orthogonal modes of output files (.h5, .out, .outb)");
  post_command->add_option("files", post_files, "run outputs; one table row per file and channel")->check(CLI::ExistingFile);
  post_command->add_option("--channels", post_options.channels, "channels to tabulate (default: all)")->delimiter(',');
  post_command->add_option("--window", post_window, "analyse only T0 T1 [s] (e.g. 200 800 after the start-up transient)")->expected(2);
  post_command->add_option("--del-config", del_config,
                   "YAML: per channel wohler_exponent, ultimate_load (Goodman), goodman_fixed_mean; `default` for all; "
                   "equivalent_frequency_hz (default 1)")
      ->check(CLI::ExistingFile);
  post_command->add_option("--residue", residue, "rainflow residue as half cycles (ASTM, MLife; default) or full cycles")
      ->check(CLI::IsMember({"half", "full"}));
  post_command->add_flag("--psd", post_options.psd, "Welch PSD (Hann, 50 % overlap) of the tabulated channels");
  post_command->add_option("--psd-channels", post_options.psd_channels, "Welch PSD of these channels instead")->delimiter(',');
  post_command->add_option("--segment", post_options.segment_s, "Welch segment length [s] (default 100: Δf = 0.01 Hz)")
      ->check(positive("a positive number of seconds"));
  post_command->add_option("--pom", post_options.pom_pattern,
                   "proper orthogonal modes of the channels matching this glob (nodal deflections, e.g. 'B1N*TDxr')");
  post_command->add_flag("--pom-remove-means", post_options.pom_remove_means,
                 "subtract each node's mean before the SVD (the seed decomposes the deflections as they are)");
  post_command->add_option("-o,--output", post_outputs, "write the results to OUT.h5 and/or OUT.csv (repeat -o for both)");
  post_command->add_option("--plot", plot_dir, "write PNG plots to DIR with tools/plot (needs Debian's python3-matplotlib)");
  post_command->add_option("--lifetime", lifetime_spec,
                   "lifetime DELs over a wind-speed distribution: YAML with runs (file, wind_speed_m_s), "
                   "wind_distribution, design_life_years, bin_width_m_s and a fatigue section (see modules/post/README.md)")
      ->check(CLI::ExistingFile);

  SweepRequest sweep_request;
  std::string sweep_output_dir, sweep_base_deck;
  int sweep_max_running = 0;
  bool sweep_list = false, sweep_slurm = false, sweep_collect = false;
  auto* sweep = app.add_subcommand("sweep", "design-load-case sweep: expand a sweep spec into cases, run them locally or "
                                            "as a Slurm job array (resumable), and collect the load table");
  sweep->add_option("spec", sweep_request.spec, "sweep spec (YAML; driver/app/sweep/README.md)")->required()->check(CLI::ExistingFile);
  auto* sweep_list_flag = sweep->add_flag("--list", sweep_list, "print the expanded cases and do nothing else");
  sweep->add_option("-j,--jobs", sweep_request.jobs, "local processes at once (default 1)")->check(positive("a positive whole number"));
  auto* sweep_slurm_flag = sweep->add_flag("--slurm", sweep_slurm, "write the case decks and a job-array script and submit it with sbatch");
  auto* sweep_collect_flag = sweep->add_flag("--collect", sweep_collect, "write the load table from the cases that have finished");
  sweep->add_option("--output-dir", sweep_output_dir, "output folder (default: the spec's sweep.output_dir, or runs/sweeps/<name>)");
  sweep->add_option("--base-deck", sweep_base_deck,
                    "scene deck every case includes, instead of the spec's sweep.base_deck: the same cases, seeds and "
                    "events on another model (give another --output-dir too)")
      ->check(CLI::ExistingFile);
  sweep->add_option("--partition", sweep_request.slurm.partition, "Slurm partition (--slurm)");
  sweep->add_option("--time", sweep_request.slurm.time_limit, "Slurm time limit per array task, e.g. 02:00:00 (--slurm)");
  sweep->add_option("--account", sweep_request.slurm.account, "Slurm account charged for the job (--slurm; over the spec's slurm.account)");
  sweep->add_option("--qos", sweep_request.slurm.qos, "Slurm quality of service (--slurm; over the spec's slurm.qos)");
  sweep->add_option("--mem", sweep_request.slurm.memory, "memory per array task, e.g. 2G (--slurm; over the spec's slurm.mem)");
  sweep->add_option("--cases-per-task", sweep_request.slurm.cases_per_task,
                    "cases run one after the other in each array task, for short cases (--slurm; default 1)")
      ->check(positive("a positive whole number"));
  sweep->add_option("--max-running", sweep_max_running, "array tasks running at once: --array=0-N%M (--slurm)")
      ->check(positive("a positive whole number"));
  sweep->add_flag("--dry-run", sweep_request.dry_run, "with --slurm: write everything and print the sbatch command, submit nothing");
  auto* sweep_fd_flag = sweep->add_flag("--frequency-domain", sweep_request.frequency_domain,
                                        "screen every case in the frequency domain and rank them (runs none)");
  sweep_fd_flag->excludes(sweep_slurm_flag)->excludes(sweep_collect_flag)->excludes(sweep_list_flag);
  sweep_list_flag->excludes(sweep_slurm_flag)->excludes(sweep_collect_flag);
  sweep_slurm_flag->excludes(sweep_collect_flag);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : kExitInput;
  }
  if (help_deck) {
    fmt::print("Toy coupled-oscillator scene:\n{}\nBeam scene (a deck with a top-level `beam`):\n{}\n"
               "Pipe scene (a deck with a top-level `pipe`):\n{}\n"
               "Platform-loads scene (a deck with a top-level `platform_motion`):\n{}\n"
               "Floating-turbine scene (a deck with a top-level `structure`):\n{}\n"
               "Slender-body scene (a deck with a top-level `slender`):\n{}\n"
               "Turbulence deck (`fowtsim turbulence DECK`):\n{}\nFatigue configuration (`fowtsim post --del-config FILE`):\n{}\n"
               "Lifetime specification (`fowtsim post --lifetime FILE`):\n{}",
               io::describe_schema(toy_scene_schema()), io::describe_schema(beam_scene_schema()),
               io::describe_schema(pipe_scene_schema()),
               io::describe_schema(platform_scene_schema()), io::describe_schema(floating_scene_schema()),
               io::describe_schema(slender_scene_schema()),
               io::describe_schema(io::Schema::map({{"wind", wind_schema()}})), io::describe_schema(fatigue_config_schema()),
               io::describe_schema(lifetime_spec_schema()));
    fmt::print("\nSweep spec (`fowtsim sweep SPEC`):\n{}", io::describe_schema(sweep::sweep_spec_schema()));
    return 0;
  }
  if (app.get_subcommands().empty()) {
    fmt::print(stderr, "{}", app.help());
    return kExitInput;
  }
  try {
    if (*run) {
      if (!out_base.empty()) request.output_base = out_base;
      if (!out_format.empty()) request.output_format = out_format;
      if (tmax > 0) request.t_max_s = tmax;
      if (dt > 0) request.dt_s = dt;
      if (segments > 0) request.beam_segments = segments;
      if (!integrator.empty()) request.beam_integrator = integrator;
      if (matrix_age > 0) request.beam_matrix_max_age = matrix_age;
      if (checkpoint_every > 0) request.checkpoint_every_s = checkpoint_every;
      if (!restart.empty()) request.restart_path = restart;
      if (!turbulence_cache.empty()) request.turbulence_cache = turbulence_cache;
      return run_command(request);
    }
    if (*compare) {
      return compare_command(ref, test, channels, rtol_opt->count() ? std::optional(rtol) : std::nullopt,
                             atol_opt->count() ? std::optional(atol) : std::nullopt, tolerance_file, window, stats, stats_percent,
                             wohler > 0 ? std::optional(wohler) : std::nullopt);
    }
    if (*post_command) {
      for (const std::string& f : post_files) post_options.files.emplace_back(f);
      for (const std::string& o : post_outputs) post_options.outputs.emplace_back(o);
      if (post_window.size() == 2) post_options.window = post::TimeWindow{post_window[0], post_window[1]};
      if (!del_config.empty()) post_options.del_config = del_config;
      post_options.residue = residue == "full" ? post::ResidueCounting::full_cycles : post::ResidueCounting::half_cycles;
      if (!plot_dir.empty()) post_options.plot_dir = plot_dir;
      if (!lifetime_spec.empty()) post_options.lifetime_spec = lifetime_spec;
      return run_post_command(post_options, stdout);
    }
    if (*sweep) {
      sweep_request.action = sweep_list      ? SweepRequest::Action::list
                             : sweep_slurm   ? SweepRequest::Action::slurm
                             : sweep_collect ? SweepRequest::Action::collect
                                             : SweepRequest::Action::run_local;
      if (!sweep_output_dir.empty()) sweep_request.output_dir = sweep_output_dir;
      if (!sweep_base_deck.empty()) sweep_request.base_deck = sweep_base_deck;
      if (sweep_max_running > 0) sweep_request.slurm.max_running = sweep_max_running;
      return run_sweep_command(sweep_request, stdout);
    }
    if (*modes)
      return run_modes_command(modes_deck, modes_settings,
                               modes_output.empty() ? std::nullopt : std::optional<std::filesystem::path>(modes_output), stdout);
    if (*screen)
      return run_screen_command(screen_deck, screen_settings,
                                screen_output.empty() ? std::nullopt : std::optional<std::filesystem::path>(screen_output), stdout);
    if (*turbulence) return run_turbulence_command(wind_deck, wind_out.empty() ? std::nullopt : std::optional<std::filesystem::path>(wind_out), stdout);
    if (*verify) return verify_command(cases, shared_dir);
    set_shared_dir(shared_dir);
    if (*bench) return bench_command(bench_cases);
  } catch (const NumericalError& e) {
    std::fflush(stdout);
    fmt::print(stderr, "\nfowtsim: numerical failure: {}\nOutputs keep every step up to the failure.\n", e.what());
    return kExitNumerical;
  } catch (const std::exception& e) {
    std::fflush(stdout);
    fmt::print(stderr, "fowtsim: {}\n", e.what());
    return kExitInput;
  }
  return 0;
}
