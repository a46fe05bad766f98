#include "verify/reports.hpp"

#include <cmath>

#include <fmt/format.h>

#include "run/interrupt.hpp"

namespace fowtsim::driver {

void print_run_summary(std::FILE* out, const RunReport& r) {
  fmt::print(out, "── fowtsim run summary ──────────────────────────────\n");
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
  for (const auto& p : r.outputs) fmt::print(out, "  output           {}\n", p.string());
  fmt::print(out, "  warnings         {}\n", r.warnings.empty() ? "none" : std::to_string(r.warnings.size()));
  for (const auto& w : r.warnings) fmt::print(out, "    - {}\n", w);
  for (const auto& line : r.results) fmt::print(out, "  {}\n", line);
}

void print_comparison(std::FILE* out, const ComparisonReport& r) {
  fmt::print(out, "compared {} samples over {:.6g}–{:.6g} s{}\n", r.samples, r.t_start_s, r.t_end_s,
             r.statistics ? " (statistics)" : "");
  auto tolerance = [](const ChannelTolerance& t) {
    return t.range_atol > 0 ? fmt::format("{:.1e}+{:.1e}·range", t.rtol, t.range_atol) : fmt::format("{:.1e}/{:.1e}", t.rtol, t.atol);
  };
  if (r.statistics) {
    const std::size_t shown = r.wohler_exponent ? 5 : 4;
    fmt::print(out, "{:<18} {:>8} {:>23} {:>23} {:>23} {:>23}", "channel", "unit", "mean ref → test", "std ref → test",
               "min ref → test", "max ref → test");
    if (r.wohler_exponent) fmt::print(out, " {:>23}", fmt::format("DEL(m={:g}) ref → test", *r.wohler_exponent));
    fmt::print(out, " {:>22}  {}\n", "tolerance", "result");
    for (const auto& c : r.channels) {
      fmt::print(out, "{:<18} {:>8}", c.name, c.unit);
      for (std::size_t k = 0; k < shown; ++k) fmt::print(out, " {:>11.4g}→{:<11.4g}", c.reference_statistics[k], c.test_statistics[k]);
      fmt::print(out, " {:>22}  {}\n", tolerance(c.tolerance), c.pass ? "PASS" : "FAIL");
    }
  } else {
    fmt::print(out, "{:<18} {:>8} {:>12} {:>11} {:>11} {:>9} {:>22}  {}\n", "channel", "unit", "max|err|", "rms/rms",
               "rms/range", "corr", "tolerance", "result");
    for (const auto& c : r.channels) {
      // A constant reference has no range or correlation to speak of: say so instead of nan.
      const std::string rms_rms = std::isfinite(c.rms_error_over_rms) ? fmt::format("{:.3e}", c.rms_error_over_rms) : "constant";
      const std::string rms_range = c.constant_reference ? "constant" : fmt::format("{:.3e}", c.rms_error_over_range);
      const std::string corr = std::isfinite(c.correlation) ? fmt::format("{:.6f}", c.correlation) : "constant";
      fmt::print(out, "{:<18} {:>8} {:>12.4e} {:>11} {:>11} {:>9} {:>22}  {}\n", c.name, c.unit, c.max_abs_error, rms_rms,
                 rms_range, corr, tolerance(c.tolerance),
                 c.pass ? "PASS" : fmt::format("FAIL (worst at t = {:.6g} s)", c.worst_time_s));
    }
  }
  for (const auto& n : r.required_missing_names) fmt::print(out, "{:<18} missing (required)\n", n);
  for (const auto& n : r.missing_in_test) fmt::print(out, "{:<18} missing in the test file\n", n);
  for (const auto& n : r.missing_in_reference) fmt::print(out, "{:<18} missing in the reference file\n", n);
  fmt::print(out, "{}\n", r.pass() ? "PASS" : "FAIL");
}

void print_verification(std::FILE* out, const std::vector<VerificationRow>& rows) {
  fmt::print(out, "{:<10} {:<46} {:>11} {:<18} {:<46} {}\n", "case", "metric", "value", "tolerance", "source", "result");
  for (const auto& r : rows) {
    fmt::print(out, "{:<10} {:<46} {:>11.4g} {:<18} {:<46} {}\n", r.case_name, r.metric, r.value, r.tolerance,
               r.source, r.pass ? "PASS" : "FAIL");
  }
}

}  // namespace fowtsim::driver
