#include "compare/comparison_table.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

namespace fowtsim::driver {
namespace {

// How many names a one-line summary of the channels of one file lists before "…".
constexpr std::size_t kNamesShown = 10;

std::string tolerance_text(const ChannelTolerance& t) {
  return t.range_atol > 0 ? fmt::format("{:.1e}+{:.1e}·range", t.rtol, t.range_atol) : fmt::format("{:.1e}/{:.1e}", t.rtol, t.atol);
}

std::string percent(double p) { return std::isfinite(p) ? fmt::format("{:+.1f}", p) : fmt::format("{}", p); }

// What the test file calls the channel and how its values were converted, when either differs.
std::string test_note(const ChannelComparison& c) {
  std::string note;
  if (!c.test_name.empty()) note = fmt::format("test: {}", c.test_name);
  if (c.unit_factor != 1.0)
    note += fmt::format("{}test ({}) ×{:g} → ({})", note.empty() ? "" : "; ", c.test_unit, c.unit_factor, c.unit);
  return note;
}

void print_statistics(std::FILE* out, const ComparisonReport& r, std::size_t width) {
  const bool del = r.wohler_exponent.has_value();
  fmt::print(out,
             "criterion: |Δmean| ≤ {0:g} % of max(|mean ref|, std ref), |Δstd| ≤ {0:g} % of std ref{1}; "
             "Δ% = 100·(test − ref)/that scale\n",
             r.statistics_percent, del ? fmt::format(", |ΔDEL| ≤ {:g} % of DEL ref (m = {:g})", r.statistics_percent, *r.wohler_exponent) : "");
  fmt::print(out, "{:<{}} {:>8} {:>11} {:>11} {:>7} {:>11} {:>11} {:>7}", "channel", width, "unit", "mean ref", "mean test", "Δ%",
             "std ref", "std test", "Δ%");
  if (del) fmt::print(out, " {:>11} {:>11} {:>7}", "DEL ref", "DEL test", "Δ%");
  fmt::print(out, "  result\n");
  for (const auto& c : r.channels) {
    const auto& ref = c.reference_statistics;
    const auto& test = c.test_statistics;
    const auto& d = c.difference_percent;
    fmt::print(out, "{:<{}} {:>8} {:>11.5g} {:>11.5g} {:>7} {:>11.5g} {:>11.5g} {:>7}", c.name, width, c.unit, ref[kMean],
               test[kMean], percent(d[kMean]), ref[kStd], test[kStd], percent(d[kStd]));
    if (del) fmt::print(out, " {:>11.5g} {:>11.5g} {:>7}", ref[kDel], test[kDel], percent(d[kDel]));
    const std::string note = test_note(c);
    fmt::print(out, "  {}{}\n", c.pass ? "PASS" : "FAIL", note.empty() ? "" : "  " + note);
  }
}

void print_samples(std::FILE* out, const ComparisonReport& r, std::size_t width) {
  fmt::print(out, "{:<{}} {:>8} {:>12} {:>11} {:>11} {:>9} {:>22}  {}\n", "channel", width, "unit", "max|err|", "rms/rms",
             "rms/range", "corr", "tolerance", "result");
  for (const auto& c : r.channels) {
    // A constant reference has no range or correlation to speak of: say so instead of nan.
    const std::string rms_rms = std::isfinite(c.rms_error_over_rms) ? fmt::format("{:.3e}", c.rms_error_over_rms) : "constant";
    const std::string rms_range = c.constant_reference ? "constant" : fmt::format("{:.3e}", c.rms_error_over_range);
    const std::string corr = std::isfinite(c.correlation) ? fmt::format("{:.6f}", c.correlation) : "constant";
    const std::string note = test_note(c);
    fmt::print(out, "{:<{}} {:>8} {:>12.4e} {:>11} {:>11} {:>9} {:>22}  {}{}\n", c.name, width, c.unit, c.max_abs_error,
               rms_rms, rms_range, corr, tolerance_text(c.tolerance),
               c.pass ? "PASS" : fmt::format("FAIL (worst at t = {:.6g} s)", c.worst_time_s), note.empty() ? "" : "  " + note);
  }
}

// "a, b, c, … (first 10)": a list of names that fits on one line however long it is.
std::string first_names(const std::vector<std::string>& names) {
  const std::size_t shown = std::min(names.size(), kNamesShown);
  return fmt::format("{}{}", fmt::join(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(shown), ", "),
                     names.size() > shown ? fmt::format(", … (first {})", shown) : "");
}

// "312 channels only in the reference: a, b, c, … (first 10)".
void print_only_in(std::FILE* out, const std::vector<std::string>& names, const char* file) {
  if (names.empty()) return;
  fmt::print(out, "{} channel{} only in the {}: {}\n", names.size(), names.size() == 1 ? "" : "s", file, first_names(names));
}

}  // namespace

void print_comparison(std::FILE* out, const ComparisonReport& r) {
  fmt::print(out, "compared {} samples over {:.6g}–{:.6g} s{}\n", r.samples, r.t_start_s, r.t_end_s,
             r.statistics ? " (statistics)" : "");
  std::size_t width = 7;  // "channel"
  for (const auto& c : r.channels) width = std::max(width, c.name.size());
  if (r.statistics)
    print_statistics(out, r, width);
  else
    print_samples(out, r, width);
  fmt::print(out, "{} of {} channels within {}\n", r.passed(), r.channels.size(),
             r.statistics ? fmt::format("{:g} %", r.statistics_percent) : std::string("tolerance"));
  for (const auto& m : r.required_missing) fmt::print(out, "{}: asked for, {}\n", m.name, m.reason);
  for (const auto& m : r.refused) fmt::print(out, "{}: not compared: {}\n", m.name, m.reason);
  if (!r.invalid.empty())
    fmt::print(out, "{} channel{} marked INVALID (not computed in that run), not compared: {}\n", r.invalid.size(),
               r.invalid.size() == 1 ? "" : "s", first_names(r.invalid));
  print_only_in(out, r.missing_in_test, "reference");
  print_only_in(out, r.missing_in_reference, "test file");
  fmt::print(out, "{}\n", r.pass() ? "PASS" : "FAIL");
}

}  // namespace fowtsim::driver
