#include "verify/verify_turbine.hpp"
#include "verify/verify_cases.hpp"
#include "verify/verify_modules.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "verify/coupling_study.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

std::vector<VerificationRow> verify_coupling(std::FILE* out);  // verify_coupling.cpp
std::vector<VerificationRow> verify_beam_rollup(std::FILE* out);  // verify_beam.cpp
std::vector<VerificationRow> verify_beam_curved(std::FILE* out);
std::vector<VerificationRow> verify_beam_timestep(std::FILE* out);
std::vector<VerificationRow> verify_beam_beamdyn(std::FILE* out);
std::vector<VerificationRow> verify_beam_frequencies(std::FILE* out);
void bench_beam(std::FILE* out);
void bench_aero(std::FILE* out);       // bench_turbine.cpp
void bench_multibody(std::FILE* out);
void bench_startup(std::FILE* out);  // bench_startup.cpp
void bench_options(std::FILE* out);  // bench_options.cpp
void bench_turbine(std::FILE* out);    // bench_flexible_turbine.cpp
void bench_stability(std::FILE* out);  // bench_stability.cpp
void bench_riser(std::FILE* out);      // bench_riser.cpp
void bench_slender(std::FILE* out);    // bench_slender.cpp
std::vector<VerificationRow> verify_sea(std::FILE* out);  // verify_sea.cpp
std::vector<VerificationRow> verify_pipe(std::FILE* out);  // verify_pipe.cpp
void bench_hydro(std::FILE* out);
void bench_waves(std::FILE* out);

std::vector<std::string> verification_case_names() {
  return {"coupling", "beam-rollup", "beam-curved", "beam-timestep", "beam-beamdyn", "beam-frequencies", "pipe", "sea",
          "aero",     "wind",        "multibody",   "control",       "flexbody",     "slender",     "free-decay",   "turbine-validation",
          "turbine-oc3", "screening"};
}

std::vector<VerificationRow> run_verification_case(const std::string& name, std::FILE* out) {
  if (name == "coupling") return verify_coupling(out);
  if (name == "beam-rollup") return verify_beam_rollup(out);
  if (name == "beam-curved") return verify_beam_curved(out);
  if (name == "beam-timestep") return verify_beam_timestep(out);
  if (name == "beam-beamdyn") return verify_beam_beamdyn(out);
  if (name == "beam-frequencies") return verify_beam_frequencies(out);
  if (name == "pipe") return verify_pipe(out);
  if (name == "sea") return verify_sea(out);
  if (name == "aero") return verify_aero(out);  // verify_aero_wind.cpp
  if (name == "wind") return verify_wind(out);
  if (name == "multibody") return verify_multibody(out);  // verify_multibody_control.cpp
  if (name == "control") return verify_control(out);
  if (name == "flexbody") return verify_flexbody(out);  // verify_flexbody.cpp
  if (name == "slender") return verify_slender(out);  // verify_slender.cpp
  if (name == "screening") return verify_screening(out);  // verify_screening.cpp
  if (name == "free-decay") return verify_free_decay(out);
  if (name == "turbine-validation") return verify_turbine_validation(out);
  if (name == "turbine-oc3") return verify_turbine_oc3(out);
  std::string known;
  for (const std::string& n : verification_case_names()) known += (known.empty() ? "" : ", ") + n;
  throw InputError({"verify", {}, name, "known cases: " + known}, fmt::format("unknown verification case '{}'", name));
}

int VerificationOutcome::exit_code() const {
  if (rows.empty()) return 1;
  return std::all_of(rows.begin(), rows.end(), [](const VerificationRow& r) { return r.pass; }) ? 0 : 1;
}

VerificationOutcome run_verification(std::vector<std::string> cases, const std::filesystem::path& shared_dir,
                                     std::FILE* out) {
  if (cases.empty() || (cases.size() == 1 && cases[0] == "all")) cases = verification_case_names();
  set_shared_dir(shared_dir);
  VerificationOutcome outcome;
  for (const std::string& name : cases) {
    std::vector<VerificationRow> rows = run_verification_case(name, out);
    if (rows.empty()) {
      const std::filesystem::path reference = shared_dir / "reference";
      outcome.skipped.push_back(
          {name, std::filesystem::is_directory(reference)
                     ? std::string("the case ran no check")
                     : fmt::format("reference data not found under {} (give the folder holding reference/ with --shared DIR)",
                                   reference.string())});
    }
    for (VerificationRow& row : rows) outcome.rows.push_back(std::move(row));
  }
  return outcome;
}

void print_verification_outcome(std::FILE* out, const VerificationOutcome& outcome) {
  if (!outcome.rows.empty()) print_verification(out, outcome.rows);
  for (const SkippedCase& s : outcome.skipped) fmt::print(out, "{:<10} SKIPPED: {}\n", s.case_name, s.reason);
  const std::string skipped =
      outcome.skipped.empty() ? "" : fmt::format("; {} case{} SKIPPED", outcome.skipped.size(), outcome.skipped.size() == 1 ? "" : "s");
  if (outcome.rows.empty()) {
    fmt::print(out, "no verification check ran{}: nothing was verified\n", skipped);
  } else if (outcome.exit_code() == 0) {
    fmt::print(out, "all {} verification checks PASS{}\n", outcome.rows.size(), skipped);
  } else {
    const auto failed = std::count_if(outcome.rows.begin(), outcome.rows.end(), [](const VerificationRow& r) { return !r.pass; });
    fmt::print(out, "{} of {} verification checks FAIL{}\n", failed, outcome.rows.size(), skipped);
  }
}

std::filesystem::path source_root() { return std::filesystem::path(FOWTSIM_INPUTS_DIR).parent_path().lexically_normal(); }

std::filesystem::path default_shared_dir() {
  std::filesystem::path root = source_root();
  if (root.filename().empty()) root = root.parent_path();  // a trailing separator
  return (root.parent_path() / "shared").lexically_normal();
}

std::vector<std::string> benchmark_case_names() {
  return {"coupling", "beam", "hydro", "waves", "aero", "multibody", "startup", "options", "turbine", "stability", "riser", "slender"};
}

std::filesystem::path source_input(const std::string& relative) {
  const std::filesystem::path local = std::filesystem::path("inputs") / relative;
  if (std::filesystem::exists(local)) return local;
  return std::filesystem::path(FOWTSIM_INPUTS_DIR) / relative;
}

// Wall time against error for each coupling mode over 200 s of the toy problem. Times are from
// this one run on this machine; compare them as ratios.
void run_benchmark_case(const std::string& name, std::FILE* out) {
  if (name == "beam") return bench_beam(out);
  if (name == "hydro") return bench_hydro(out);
  if (name == "waves") return bench_waves(out);
  if (name == "aero") return bench_aero(out);
  if (name == "multibody") return bench_multibody(out);
  if (name == "startup") return bench_startup(out);
  if (name == "options") return bench_options(out);
  if (name == "turbine") return bench_turbine(out);
  if (name == "stability") return bench_stability(out);
  if (name == "riser") return bench_riser(out);
  if (name == "slender") return bench_slender(out);
  if (name != "coupling") {
    throw InputError({"bench", {}, name, "known cases: coupling, beam, hydro, waves, aero, multibody, startup, options, turbine, stability, riser, slender"}, fmt::format("unknown benchmark case '{}'", name));
  }
  const ToyProblem problem = study_problem();
  constexpr double kTmax = 200.0;
  struct Run {
    CouplingMode mode;
    int n;
    double dt;
  };
  const Run runs[] = {{CouplingMode::single_rate, 1, 0.1},        {CouplingMode::single_rate, 1, 0.025},
                      {CouplingMode::multi_rate, 16, 0.4},         {CouplingMode::multi_rate, 16, 0.1},
                      {CouplingMode::predictor_corrector, 16, 0.4}, {CouplingMode::predictor_corrector, 16, 0.1}};
  fmt::print(out, "{:<20} {:>3} {:>7} {:>11} {:>11} {:>10} {:>9}\n", "mode", "n", "ΔT [s]", "err X slow", "err q fast",
             "wall [ms]", "vs first");
  double first_wall = 0;
  for (const Run& r : runs) {
    const ErrorSample e = measure_error(problem, r.mode, r.n, r.dt, kTmax);
    const auto start = std::chrono::steady_clock::now();
    volatile double sink = run_only(problem, r.mode, r.n, r.dt, kTmax);  // keep the loop from being optimised away
    (void)sink;
    const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (first_wall == 0) first_wall = wall;
    fmt::print(out, "{:<20} {:>3} {:>7.3f} {:>11.3e} {:>11.3e} {:>10.2f} {:>8.2f}x\n", to_string(r.mode), r.n, r.dt,
               e.slow_error, e.fast_error, wall, wall / first_wall);
  }
}

}  // namespace fowtsim::driver
