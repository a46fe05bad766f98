// `fowtsim bench riser` (issue 26): seed 000 §3.5.3's top-tensioned riser (modules/beam/riser.hpp)
// — its four cases with the numbers behind the seed's conclusions, a time-step study of
// generalized-α against a fine reference (the seed's Δt = 1 ms measured against it), the real-time
// factor on one core, and the data of Figs. 3.11–3.12 as CSV files for
// modules/beam/scripts/plot_riser.py.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "fowtsim/beam/riser.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {
namespace {

namespace rs = beam::riser;

constexpr double kTend = 11.0;  // the 1 s ramp and one sway period
const std::vector<double> kSnapshots{1.0, 3.5, 6.0, 8.5, 11.0};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void write_csv(const std::filesystem::path& dir, char c, const rs::RiserRun& r) {
  std::ofstream shapes(dir / fmt::format("riser_{}_shapes.csv", c));
  shapes << "t_s,point,x_m,y_m,z_m\n";
  for (std::size_t k = 0; k < r.snapshots_m.size(); ++k)
    for (std::size_t i = 0; i < r.snapshots_m[k].size(); ++i) {
      const Vec3& x = r.snapshots_m[k][i];
      shapes << fmt::format("{},{},{:.9g},{:.9g},{:.9g}\n", r.snapshot_times_s[k], i, x.x(), x.y(), x.z());
    }
  std::ofstream envelope(dir / fmt::format("riser_{}_envelope.csv", c));
  envelope << "s_m,max_bending_moment_N_m\n";
  for (std::size_t j = 0; j < r.section_s_m.size(); ++j)
    envelope << fmt::format("{:.9g},{:.9g}\n", r.section_s_m[j], r.max_bending_moment_n_m[j]);
}

}  // namespace

void bench_riser(std::FILE* out) {
  const auto dir = std::filesystem::temp_directory_path() / "fowtsim_bench_riser";
  std::filesystem::create_directories(dir);
  fmt::print(out, "Seed 000 §3.5.3 riser, 100 volumes, Δt 1 ms, {} s (ramp + one sway period), from the static equilibrium\n", kTend);
  fmt::print(out, "{:>4} | {:>14} | {:>14} | {:>14} | {:>14} | {:>10}\n", "case", "max |M| [N·m]", "at bottom", "at top",
             "max defl. [m]", "wall [s]");
  rs::RiserRun run[4];
  for (int k = 0; k < 4; ++k) {
    const char c = static_cast<char>('a' + k);
    const auto start = std::chrono::steady_clock::now();
    run[k] = rs::simulate(rs::seed_case(c), 100, 1e-3, kTend, kSnapshots);
    const double wall = seconds_since(start);
    const rs::RiserRun& r = run[k];
    fmt::print(out, "{:>4} | {:14.4e} | {:14.4e} | {:14.4e} | {:14.4f} | {:10.3f}\n", c, r.max_bending_moment_n_m_overall,
               r.max_bending_moment_n_m.front(), r.max_bending_moment_n_m.back(), r.max_deflection_m, wall);
    write_csv(dir, c, r);
  }
  auto moment = [&](int k) { return run[k].max_bending_moment_n_m_overall; };
  auto deflection = [&](int k) { return run[k].max_deflection_m; };
  fmt::print(out, "seed: tension stiffens (a)/(b): moment {:.3f}, deflection {:.3f}; the flow hardly matters (c)/(b) − 1: "
                  "moment {:+.2e}, deflection {:+.2e}; pressure softens (c)/(d): moment {:.3f}, deflection {:.3f}\n",
             moment(0) / moment(1), deflection(0) / deflection(1), moment(2) / moment(1) - 1.0, deflection(2) / deflection(1) - 1.0,
             moment(2) / moment(3), deflection(2) / deflection(3));
  fmt::print(out, "figure data (Figs. 3.11–3.12): {}; plot: python3 modules/beam/scripts/plot_riser.py {}\n\n", dir.string(),
             dir.string());

  // Time-step study, case (b) (the most deformed): the envelope's peak and the middle's sway at
  // the end against Δt = 0.125 ms; a Δt fails when a step is refused (non-finite, or an increment
  // beyond the small-angle limit).
  const rs::RiserSetup study = rs::seed_case('b');
  const rs::RiserRun reference = rs::simulate(study, 100, 1.25e-4, kTend, {}, 80);
  fmt::print(out, "Δt study, case (b), generalized-α ρ∞ = 0, against Δt = 0.125 ms (peak |M| {:.6e} N·m, mid sway {:.6f} m)\n",
             reference.max_bending_moment_n_m_overall, reference.final_mid_sway_m);
  fmt::print(out, "{:>8} | {:>12} | {:>12} | {:>10}\n", "Δt [ms]", "peak |M| err", "mid sway err", "x real time");
  double largest_stable = 0.0, largest_accurate = 0.0, seed_error = 0.0;
  for (const double dt : {2.5e-4, 5e-4, 1e-3, 2e-3, 4e-3, 8e-3, 1.6e-2, 3.2e-2, 6.4e-2, 0.128, 0.256, 0.512}) {
    const auto start = std::chrono::steady_clock::now();
    try {
      const int every = std::max(1, static_cast<int>(std::lround(1e-2 / dt)));  // the envelope every 10 ms
      const rs::RiserRun r = rs::simulate(study, 100, dt, kTend, {}, every);
      const double speed = kTend / seconds_since(start);
      const double e_m = std::abs(r.max_bending_moment_n_m_overall / reference.max_bending_moment_n_m_overall - 1.0);
      const double e_s = std::abs(r.final_mid_sway_m - reference.final_mid_sway_m) / std::abs(reference.final_mid_sway_m);
      fmt::print(out, "{:8.3g} | {:12.3e} | {:12.3e} | {:10.1f}\n", dt * 1e3, e_m, e_s, speed);
      largest_stable = dt;
      if (std::max(e_m, e_s) < 1e-2) largest_accurate = dt;
      if (dt == 1e-3) seed_error = std::max(e_m, e_s);
    } catch (const NumericalError& e) {
      fmt::print(out, "{:8.3g} | fails: {}\n", dt * 1e3, e.what());
      break;
    }
  }
  fmt::print(out, "largest Δt that runs: {:.3g} ms; largest within 1 % of the reference: {:.3g} ms; the seed's 1 ms: {:.2e}\n\n",
             largest_stable * 1e3, largest_accurate * 1e3, seed_error);

  // Real-time factor: case (a) at the seed's Δt, no envelope sampling, best of three, by the wall
  // clock and by the process's CPU time (on a shared machine the wall clock counts other jobs too).
  double best = std::numeric_limits<double>::infinity(), best_cpu = best;
  for (int k = 0; k < 3; ++k) {
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu = std::clock();
    rs::simulate(rs::seed_case('a'), 100, 1e-3, kTend, {}, std::numeric_limits<int>::max());
    best = std::min(best, seconds_since(start));
    best_cpu = std::min(best_cpu, static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC);
  }
  fmt::print(out, "real-time factor, case (a), 100 volumes, Δt 1 ms, one thread: {:.1f}x by the wall clock, {:.1f}x by CPU time "
                  "({:.3f} s, {:.3f} s CPU for {} s; issue 26 asks ≥ 20x)\n",
             kTend / best, kTend / best_cpu, best, best_cpu, kTend);
}

}  // namespace fowtsim::driver
