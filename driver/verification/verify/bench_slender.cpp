// `fowtsim bench slender`: issue 25's performance targets, measured and printed (wall time on a
// shared machine is no pass/fail criterion): one frequency-domain case of the seed's riser and of
// the OC3 tower body under 10 ms (model, modes, wave table, drag linearisation and RMS profiles:
// all of solve_slender), the time-domain riser at ≥ 100× real time, and one screening case of the
// OC3 turbine under 100 ms. Each the best of three runs: the least disturbed is the cost.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>

#include <fmt/format.h>

#include "scenes/floating_screening.hpp"
#include "scenes/slender_analysis.hpp"
#include "scenes/slender_scene.hpp"

namespace fowtsim::driver {

std::filesystem::path source_input(const std::string& relative);  // verify_cases.cpp

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Cost {
  double wall_s = INFINITY, cpu_s = INFINITY;  // best of three each
};

// Wall and process CPU time of solve_slender on a shipped deck under `settings` (CPU time: what
// the case costs when the machine's other jobs take cores from it).
Cost best_solve(const std::string& deck, const std::vector<std::string>& settings, SlenderResults& results) {
  const SlenderCase c = read_slender_case(std::filesystem::absolute(source_input("slender/" + deck)), settings);
  Cost best;
  for (int k = 0; k < 3; ++k) {
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu = std::clock();
    results = solve_slender(c.deck, c.dt_s, c.t_max_s);
    best.cpu_s = std::min(best.cpu_s, static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC);
    best.wall_s = std::min(best.wall_s, seconds_since(start));
  }
  return best;
}

}  // namespace

void bench_slender(std::FILE* out) {
  fmt::print(out, "slender bodies (seed 004, issue 25): best of 3 wall times\n");
  for (const char* deck : {"riser_jonswap.yaml", "oc3_tower_jonswap.yaml"}) {
    SlenderResults r;
    const Cost s = best_solve(deck, {"analysis.domain=frequency"}, r);
    fmt::print(out, "  FD {:<24} {:>4} strips, {:>2} shapes, {:>2} modes, {:>3} frequencies, {:>2} drag iterations: {:6.2f} ms wall, {:6.2f} ms CPU"
                    "  (target < 10 ms)\n",
               deck, r.model.strips.x_m.size(), r.model.mass.rows(), r.modes.omega_rad_s.size(),
               jonswap_grid(read_slender_case(std::filesystem::absolute(source_input(std::string("slender/") + deck))).deck.sea).omega_rad_s.size(),
               r.drag_iterations, 1e3 * s.wall_s, 1e3 * s.cpu_s);
  }
  {
    const SlenderCase c = read_slender_case(std::filesystem::absolute(source_input("slender/riser_jonswap.yaml")));
    SlenderResults r;
    const Cost s = best_solve("riser_jonswap.yaml", {"analysis.domain=time"}, r);
    fmt::print(out, "  TD riser_jonswap.yaml      {:.0f} s of sea in steps of {:g} s (RK4, nonlinear drag): {:.3f} s wall, {:.0f}× real time  "
                    "(target ≥ 100×)\n",
               c.t_max_s, c.dt_s, s.wall_s, c.t_max_s / s.wall_s);
  }
  double best = INFINITY;
  for (int k = 0; k < 3; ++k)
    best = std::min(best, screen_floating(std::filesystem::absolute(source_input("oc3_hywind/turbine_ntm_12mps_irregular.yaml"))).seconds_total());
  fmt::print(out, "  screening oc3_hywind/turbine_ntm_12mps_irregular.yaml (1200 frequencies): {:.1f} ms  (target < 100 ms)\n", 1e3 * best);
}

}  // namespace fowtsim::driver
