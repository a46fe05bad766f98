#include "verify/reports.hpp"

#include <cmath>

#include <fmt/format.h>

#include "run/interrupt.hpp"

namespace fowtsim::driver {

void print_run_summary(std::FILE* out, const RunReport& r) {
  fmt::print(out, "── fowtsim run summary ──────────────────────────────\n");
  if (r.time_loop) {
    fmt::print(out, "  simulated time   {:.3f} s ({} large steps × {} substeps, {})\n", r.simulated_s, r.large_steps,
               r.substeps, r.coupling);
    if (r.interrupted_by)
      fmt::print(out, "  status           interrupted at t = {:.6g} s of {:.6g} s ({}): the outputs hold every step up to it\n",
                 r.simulated_s, r.t_max_s, signal_name(r.interrupted_by));
    const auto factor = [&](double wall_s) { return wall_s > 0 ? r.simulated_s / wall_s : INFINITY; };
    fmt::print(out, "  wall time        {:.3f} s time loop; {:.3f} s in all (decks, set-up of wind, sea and blades, output)\n",
               r.wall_s, r.total_wall_s);
    fmt::print(out, "  real-time factor {:.1f}x faster than real time in the time loop; {:.1f}x in all\n", factor(r.wall_s),
               factor(r.total_wall_s));
  } else {
    fmt::print(out, "  solved           {}\n", r.coupling);
    fmt::print(out, "  wall time        {:.3f} s in all (deck, solution, output)\n", r.total_wall_s);
  }
  for (const auto& p : r.outputs) fmt::print(out, "  output           {}\n", p.string());
  fmt::print(out, "  warnings         {}\n", r.warnings.empty() ? "none" : std::to_string(r.warnings.size()));
  for (const auto& w : r.warnings) fmt::print(out, "    - {}\n", w);
  for (const auto& line : r.results) fmt::print(out, "  {}\n", line);
}

void print_verification(std::FILE* out, const std::vector<VerificationRow>& rows) {
  fmt::print(out, "{:<10} {:<46} {:>11} {:<18} {:<46} {}\n", "case", "metric", "value", "tolerance", "source", "result");
  for (const auto& r : rows) {
    fmt::print(out, "{:<10} {:<46} {:>11.4g} {:<18} {:<46} {}\n", r.case_name, r.metric, r.value, r.tolerance,
               r.source, r.pass ? "PASS" : "FAIL");
  }
}

}  // namespace fowtsim::driver
