// `fowtsim verify coupling`: error vs ΔT and n, observed order and largest stable ΔT of the three
// coupling modes on the toy coupled oscillators (exact solution by matrix exponential).
#include <cmath>

#include <fmt/format.h>

#include "verify/verify_cases.hpp"
#include "verify/coupling_study.hpp"

namespace fowtsim::driver {
namespace {

constexpr double kTmax = 20.0, kDtStart = 0.1, kHorizon = 200.0;
constexpr int kLevels = 5;

struct Config {
  CouplingMode mode;
  int substeps;
};
constexpr Config kConfigs[] = {{CouplingMode::single_rate, 1},         {CouplingMode::multi_rate, 4},
                               {CouplingMode::multi_rate, 16},         {CouplingMode::predictor_corrector, 4},
                               {CouplingMode::predictor_corrector, 16}};

void print_order_table(std::FILE* out, const std::vector<OrderRow>& rows) {
  fmt::print(out, "Error vs ΔT (max over 0–{} s, relative to the exact solution's max)\n", kTmax);
  fmt::print(out, "{:<20} {:>3} {:>9} {:>10} {:>11} {:>11}\n", "mode", "n", "ΔT [s]", "Δt [s]", "err X slow", "err q fast");
  for (const OrderRow& row : rows) {
    for (const ErrorSample& s : row.samples) {
      fmt::print(out, "{:<20} {:>3} {:>9.5f} {:>10.6f} {:>11.3e} {:>11.3e}\n", to_string(row.mode), row.substeps,
                 s.dt_coupling_s, s.dt_coupling_s / row.substeps, s.slow_error, s.fast_error);
    }
    fmt::print(out, "{:<20} {:>3} observed order: slow {:.2f}, fast {:.2f}\n", "", "", row.slow_order, row.fast_order);
  }
}

}  // namespace

std::vector<VerificationRow> verify_coupling(std::FILE* out) {
  const ToyProblem problem = study_problem();
  std::vector<OrderRow> orders;
  std::vector<StabilityResult> stability;
  for (const Config& c : kConfigs) {
    orders.push_back(measure_order(problem, c.mode, c.substeps, kDtStart, kLevels, kTmax));
    stability.push_back(measure_stability(problem, c.mode, c.substeps, 0.01, 5.0, kHorizon));
  }
  print_order_table(out, orders);
  // RK4 is stable for |λΔt| < 2√2 on the imaginary axis; the fast subsystem has |λ| ≈ 20 rad/s.
  const double fast_limit = 2.0 * std::sqrt(2.0) / std::sqrt(problem.fast.stiffness_N_m / problem.fast.mass_kg);
  fmt::print(out, "\nStability (energy < 2 E0 over {} s; ΔT grid ratio 2^(1/8))\n", kHorizon);
  fmt::print(out, "{:<20} {:>3} {:>16} {:>16} {:>18}\n", "mode", "n", "stable ΔT ≤ [s]", "unstable at [s]", "n·2√2/ω_fast [s]");
  for (const StabilityResult& s : stability) {
    fmt::print(out, "{:<20} {:>3} {:>16.4f} {:>16.4f} {:>18.4f}\n", to_string(s.mode), s.substeps,
               s.largest_stable_dt_s, s.first_unstable_dt_s, s.substeps * fast_limit);
  }
  fmt::print(out, "\n");

  std::vector<VerificationRow> rows;
  const std::string lag = "load lag of one ΔT: first order";
  for (const OrderRow& o : orders) {
    const std::string label = fmt::format("{} n={}", to_string(o.mode), o.substeps);
    rows.push_back({"coupling", label + ": order (slow X)", o.slow_order, "1 ± 0.1", lag, std::abs(o.slow_order - 1.0) <= 0.1});
  }
  const double mr = orders[2].samples.back().slow_error, pc = orders[4].samples.back().slow_error;
  rows.push_back({"coupling", "pc/mr slow error at ΔT=6.25 ms, n=16", pc / mr, "< 0.02",
                  "corrector applies its own interval's loads", pc / mr < 0.02});
  for (const StabilityResult& s : stability) {
    const double limit = s.substeps * fast_limit;
    const bool bracketed = s.largest_stable_dt_s <= limit && s.first_unstable_dt_s > limit;
    rows.push_back({"coupling", fmt::format("{} n={}: largest stable ΔT [s]", to_string(s.mode), s.substeps),
                    s.largest_stable_dt_s, fmt::format("brackets {:.4f}", limit), "RK4 limit 2√2/ω_fast × n", bracketed});
  }
  return rows;
}

}  // namespace fowtsim::driver
