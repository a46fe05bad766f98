// `fowtsim bench turbine` (issue 12, verification 5): the OC3 load case with flexible blades —
// turbulent wind (the deck's IEC field, generated once), irregular sea, controller — over 60 s,
// run time against the error of the blade-root flap moment and the tip flap deflection relative
// to a converged reference (49 finite volumes, Δt = 1 ms, ΔT = 5 ms, predictor–corrector,
// inductions solved at every small step), for every coupling mode, Δt ∈ {1, 2.5, 5, 10} ms,
// ΔT ∈ {5, 10, 20, 40} ms and 12/23/49 finite volumes; then the Pareto front. Printed, never
// asserted: one run on this machine, compare as ratios.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "run/turbulence_command.hpp"
#include "verify/verify_cases.hpp"
#include "fowtsim/io/readers.hpp"
#include "run/run_scene.hpp"

namespace fowtsim::driver {


namespace {

struct Case {
  std::string mode;
  int segments;
  double dt_large_s, dt_small_s;
  bool induction_every_step = false;
};

struct Result {
  Case c;
  double wall_s = 0.0;
  double flap_moment_error = 0.0, flap_tip_error = 0.0;
  bool ok = true;
};

constexpr double kTmax = 60.0, kCompareFrom = 20.0, kSample = 0.04;

std::vector<double> column(const io::ChannelTable& t, const char* name) { return t.columns[t.find(name).value()]; }

// RMS of (test − reference) / RMS of the reference over the common samples after kCompareFrom.
double relative_rms(const io::ChannelTable& ref, const io::ChannelTable& test, const char* name) {
  const auto tr = ref.time(), a = column(ref, name), b = column(test, name);
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < tr.size() && i < b.size(); ++i)
    if (tr[i] >= kCompareFrom) {
      num += (b[i] - a[i]) * (b[i] - a[i]);
      den += a[i] * a[i];
    }
  return std::sqrt(num / den);
}

}  // namespace

void bench_turbine(std::FILE* out) {
  const auto dir = std::filesystem::temp_directory_path() / "fowtsim_bench_turbine";
  std::filesystem::create_directories(dir);
  fmt::print(out, "OC3-Hywind with flexible blades, 60 s of the OC3 load case (IEC NTM 12 m/s field generated once, JONSWAP Hs 6 m)\n");
  std::FILE* quiet = std::fopen("/dev/null", "w");
  run_turbulence_command(std::filesystem::absolute(source_input("wind/oc3_ntm_12mps.yaml")), dir / "wind.bts", quiet ? quiet : out);
  if (quiet) std::fclose(quiet);
  const auto input = [](const std::string& relative) { return std::filesystem::absolute(source_input(relative)); };
  const auto oc3 = input("oc3_hywind");
  auto deck_for = [&](const Case& c) {
    const auto path = dir / "case.yaml";
    std::ofstream(path) << "include: [" << (oc3 / "structure.yaml").string() << ", " << (oc3 / "hydro.yaml").string() << ", "
                        << (oc3 / "mooring.yaml").string() << ", " << (oc3 / "controller.yaml").string() << ", "
                        << (oc3 / "sea_oc3_deck.yaml").string() << ", " << input("nrel5mw/aero.yaml").string() << ", "
                        << input("nrel5mw/blade_structure.yaml").string() << "]\n"
                        << fmt::format("simulation: {{t_max_s: {}, dt_s: {}}}\n", kTmax, c.dt_large_s)
                        << fmt::format("output: {{format: out, decimation: {}, channels: [RootMyc1, OoPDefl1]}}\n",
                                       std::lround(kSample / c.dt_large_s))
                        << "structure: {initial_conditions: {rotor_speed_rpm: 12.1}}\n"
                        << "wind: {model: bts, file: " << (dir / "wind.bts").string() << ", speed_m_s: 12.0, reference_height_m: 90.0}\n"
                        << fmt::format("blades: {{segments: {}, coupling: {}, substeps: {}, induction: {}}}\n", c.segments, c.mode,
                                       std::lround(c.dt_large_s / c.dt_small_s), c.induction_every_step ? "small_step" : "large_step");
    return path;
  };
  auto run = [&](const Case& c, const std::filesystem::path& base) {
    RunRequest r;
    r.deck_path = deck_for(c);
    r.output_base = base;
    r.output_format = "out";
    const auto start = std::chrono::steady_clock::now();
    run_scene(r, nullptr);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };

  const Case reference{"predictor_corrector", 49, 0.005, 0.001, true};
  const double ref_wall = run(reference, dir / "reference");
  const io::ChannelTable ref = io::read_channels(dir / "reference.out");
  fmt::print(out, "reference: 49 volumes, Δt 1 ms, ΔT 5 ms, predictor_corrector, inductions every small step: {:.1f} s wall ({:.1f}× real time)\n",
             ref_wall, kTmax / ref_wall);

  std::vector<Case> cases;
  for (const int segments : {12, 23, 49})
    for (const double dt_large : {0.005, 0.01, 0.02, 0.04}) {
      for (const double dt_small : {0.001, 0.0025, 0.005, 0.01}) {
        const double n = dt_large / dt_small;
        if (n < 1.5 || std::abs(n - std::round(n)) > 1e-9) continue;
        cases.push_back({"multi_rate", segments, dt_large, dt_small});
        cases.push_back({"predictor_corrector", segments, dt_large, dt_small});
      }
      if (dt_large <= 0.01) cases.push_back({"single_rate", segments, dt_large, dt_large});
    }
  std::vector<Result> results;
  fmt::print(out, "{} cases (minutes): error = RMS(test − reference)/RMS(reference) over 20–60 s\n", cases.size());
  for (const Case& c : cases) {
    Result r{c};
    try {
      r.wall_s = run(c, dir / "test");
      const io::ChannelTable test = io::read_channels(dir / "test.out");
      r.flap_moment_error = relative_rms(ref, test, "RootMyc1");
      r.flap_tip_error = relative_rms(ref, test, "OoPDefl1");
    } catch (const std::exception& e) {
      r.ok = false;
    }
    results.push_back(r);
    std::fprintf(stderr, "\r%zu/%zu", results.size(), cases.size());
  }
  std::fprintf(stderr, "\n");
  std::sort(results.begin(), results.end(), [](const Result& a, const Result& b) { return a.wall_s < b.wall_s; });
  fmt::print(out, "{:<20} {:>4} {:>8} {:>8} {:>9} {:>9} {:>12} {:>12} {:>7}\n", "mode", "vol.", "ΔT [ms]", "Δt [ms]", "wall [s]",
             "× real", "RootMyc1 err", "OoPDefl1 err", "Pareto");
  double best = 1e300;
  for (const Result& r : results) {
    const double err = std::max(r.flap_moment_error, r.flap_tip_error);
    const bool front = r.ok && err < best;
    if (front) best = err;
    if (!r.ok) {
      fmt::print(out, "{:<20} {:>4} {:>8.1f} {:>8.1f}  failed\n", r.c.mode, r.c.segments, 1e3 * r.c.dt_large_s, 1e3 * r.c.dt_small_s);
      continue;
    }
    fmt::print(out, "{:<20} {:>4} {:>8.1f} {:>8.1f} {:>9.2f} {:>9.1f} {:>12.2e} {:>12.2e} {:>7}\n", r.c.mode, r.c.segments,
               1e3 * r.c.dt_large_s, 1e3 * r.c.dt_small_s, r.wall_s, kTmax / r.wall_s, r.flap_moment_error, r.flap_tip_error,
               front ? "*" : "");
  }
  fmt::print(out, "(* Pareto front: no faster case has a smaller error; wall times include reading the decks; one run on this machine)\n");
}

}  // namespace fowtsim::driver
