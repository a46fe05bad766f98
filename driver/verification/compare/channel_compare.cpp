#include "compare/channel_compare.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "compare/window_statistics.hpp"
#include "fowtsim/post/damage_equivalent_load.hpp"
#include "fowtsim/post/rainflow.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/core/interpolation.hpp"

namespace fowtsim::driver {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Statistics {
  double mean = 0, rms = 0, min = 0, max = 0;
};

Statistics statistics(const std::vector<double>& v) {
  Statistics s{0, 0, v.front(), v.front()};
  for (double x : v) {
    s.mean += x;
    s.rms += x * x;
    s.min = std::min(s.min, x);
    s.max = std::max(s.max, x);
  }
  s.mean /= static_cast<double>(v.size());
  s.rms = std::sqrt(s.rms / static_cast<double>(v.size()));
  return s;
}

// MLife's DEL of a series over its duration (f_eq 1 Hz, residue as half cycles, no Goodman).
double damage_equivalent_load(const std::vector<double>& values, const std::vector<double>& time, double wohler_exponent) {
  post::FatigueParams params;
  params.wohler_exponent = wohler_exponent;
  return post::damage_equivalent_load(post::rainflow_cycles(values, post::ResidueCounting::half_cycles),
                                      time.back() - time.front(), params);
}

ChannelComparison compare_channel(const std::string& name, const std::string& unit, const std::vector<double>& ref,
                                  const std::vector<double>& test, const std::vector<double>& time,
                                  ChannelTolerance tol, bool compare_statistics, std::optional<double> wohler_exponent) {
  ChannelComparison c;
  c.name = name;
  c.unit = unit;
  c.tolerance = tol;
  c.worst_excess = -std::numeric_limits<double>::infinity();
  const Statistics sr0 = statistics(ref), st0 = statistics(test);
  c.constant_reference = !(sr0.max > sr0.min);
  const double atol = tol.atol + tol.range_atol * (sr0.max - sr0.min);
  if (compare_statistics) {
    const bool del = wohler_exponent && time.back() > time.front();
    c.reference_statistics = {sr0.mean, standard_deviation(ref), sr0.min, sr0.max,
                              del ? damage_equivalent_load(ref, time, *wohler_exponent) : kNaN};
    c.test_statistics = {st0.mean, standard_deviation(test), st0.min, st0.max,
                         del ? damage_equivalent_load(test, time, *wohler_exponent) : kNaN};
    for (std::size_t k = 0; k < (del ? 5u : 4u); ++k) {
      const double e = c.test_statistics[k] - c.reference_statistics[k];
      const double excess = std::isfinite(e) ? std::abs(e) - (atol + tol.rtol * std::abs(c.reference_statistics[k]))
                                             : std::numeric_limits<double>::infinity();
      c.worst_excess = std::max(c.worst_excess, excess);
      c.max_abs_error = std::max(c.max_abs_error, std::abs(e));
    }
    c.pass = c.worst_excess <= 0.0;
    return c;
  }
  std::vector<double> error(ref.size());
  for (std::size_t i = 0; i < ref.size(); ++i) {
    error[i] = test[i] - ref[i];
    // A NaN in either file must fail: NaN comparisons are false, so test for it explicitly.
    const double excess = std::isfinite(error[i]) ? std::abs(error[i]) - (atol + tol.rtol * std::abs(ref[i]))
                                                  : std::numeric_limits<double>::infinity();
    if (excess > c.worst_excess) {
      c.worst_excess = excess;
      c.worst_time_s = time[i];
    }
    c.max_abs_error = std::max(c.max_abs_error, std::abs(error[i]));
  }
  const Statistics sr = statistics(ref), se = statistics(error);
  c.rms_error_over_rms = sr.rms > 0 ? se.rms / sr.rms : kNaN;
  c.rms_error_over_range = sr.max > sr.min ? se.rms / (sr.max - sr.min) : kNaN;
  c.correlation = correlation(ref, test);
  c.pass = c.worst_excess <= 0.0;
  return c;
}

}  // namespace

bool ComparisonReport::pass() const {
  if (required_missing || channels.empty()) return false;
  return std::all_of(channels.begin(), channels.end(), [](const ChannelComparison& c) { return c.pass; });
}

ComparisonReport compare_tables(const io::ChannelTable& reference, const io::ChannelTable& test,
                                const CompareOptions& options) {
  ComparisonReport report;
  const std::vector<double>& tr = reference.time();
  const std::vector<double>& tt = test.time();
  if (tr.empty() || tt.empty()) throw InputError({"compare", {}, "Time", ""}, "a file has no time samples");
  require_strictly_increasing(tt, "test Time");
  report.t_start_s = std::max(tr.front(), tt.front());
  report.t_end_s = std::min(tr.back(), tt.back());
  report.statistics = options.statistics;
  if (options.statistics) report.wohler_exponent = options.wohler_exponent;
  if (options.window) {
    report.t_start_s = std::max(report.t_start_s, options.window->first);
    report.t_end_s = std::min(report.t_end_s, options.window->second);
  }
  // Reference samples inside the common window (1e-9 s slack for printed time values).
  std::vector<std::size_t> rows;
  std::vector<double> time;
  for (std::size_t i = 0; i < tr.size(); ++i) {
    if (tr[i] >= report.t_start_s - 1e-9 && tr[i] <= report.t_end_s + 1e-9) {
      rows.push_back(i);
      time.push_back(tr[i]);
    }
  }
  if (rows.empty()) {
    throw InputError({"compare", {}, "Time", "check that both files cover the same time span"},
                     fmt::format("no common time window: reference {}–{} s, test {}–{} s", tr.front(), tr.back(),
                                 tt.front(), tt.back()));
  }
  report.samples = rows.size();

  std::vector<std::string> wanted = options.channels;
  const bool explicit_list = !wanted.empty();
  if (!explicit_list) wanted.assign(reference.names.begin() + 1, reference.names.end());
  // A channel's name in the other file: itself, or its alias either way round.
  auto find_as = [&](const io::ChannelTable& table, const std::string& name) -> std::optional<std::size_t> {
    if (const auto i = table.find(name)) return i;
    if (const auto it = options.aliases.find(name); it != options.aliases.end()) return table.find(it->second);
    for (const auto& [a, b] : options.aliases)
      if (b == name) return table.find(a);
    return std::nullopt;
  };
  if (!explicit_list)  // with --channels only those are reported
    for (std::size_t c = 1; c < test.names.size(); ++c) {
      if (!find_as(reference, test.names[c])) report.missing_in_reference.push_back(test.names[c]);
    }

  std::vector<double> ref_values(rows.size()), test_values(rows.size());
  for (const std::string& name : wanted) {
    const auto rc = find_as(reference, name), tc = find_as(test, name);
    if (!rc || !tc) {
      if (explicit_list) {
        report.required_missing = true;
        report.required_missing_names.push_back(name);  // once, whichever file lacks it
      } else {
        if (!tc) report.missing_in_test.push_back(name);
        if (!rc) report.missing_in_reference.push_back(name);
      }
      continue;
    }
    for (std::size_t k = 0; k < rows.size(); ++k) {
      ref_values[k] = reference.columns[*rc][rows[k]];
      test_values[k] = interpolate_linear(tt, test.columns[*tc], time[k]);
    }
    const auto it = options.tolerances.find(name);
    const ChannelTolerance tol = it != options.tolerances.end() ? it->second : options.default_tolerance;
    report.channels.push_back(compare_channel(name, reference.units[*rc], ref_values, test_values, time, tol, options.statistics,
                                              options.wohler_exponent));
  }
  if (report.channels.empty() && !report.required_missing) {
    throw InputError({"compare", {}, "", "use --channels to pick channels present in both files"},
                     "the two files have no channel in common");
  }
  return report;
}

}  // namespace fowtsim::driver
