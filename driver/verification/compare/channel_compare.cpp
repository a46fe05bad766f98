#include "compare/channel_compare.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "compare/channel_units.hpp"
#include "compare/window_statistics.hpp"
#include "run/channel_names.hpp"
#include "fowtsim/post/damage_equivalent_load.hpp"
#include "fowtsim/post/rainflow.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/core/interpolation.hpp"

namespace fowtsim::driver {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// What the sample-by-sample metrics need of a series: its rms and its range.
struct Spread {
  double rms = 0, min = 0, max = 0;
};

Spread spread(const std::vector<double>& v) {
  Spread s{0, v.front(), v.front()};
  for (double x : v) {
    s.rms += x * x;
    s.min = std::min(s.min, x);
    s.max = std::max(s.max, x);
  }
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

// 100·(test − ref)/scale; a zero scale (a channel constant at zero) gives 0 % only for equal values.
double difference_percent(double ref, double test, double scale) {
  const double d = test - ref;
  if (scale > 0) return 100.0 * d / scale;
  return d == 0 ? 0.0 : std::numeric_limits<double>::infinity();
}

void compare_statistics(ChannelComparison& c, const std::vector<double>& ref, const std::vector<double>& test,
                        const std::vector<double>& time, double percent, std::optional<double> wohler_exponent) {
  const bool del = wohler_exponent && time.back() > time.front();
  c.reference_statistics = {mean(ref), standard_deviation(ref), del ? damage_equivalent_load(ref, time, *wohler_exponent) : kNaN};
  c.test_statistics = {mean(test), standard_deviation(test), del ? damage_equivalent_load(test, time, *wohler_exponent) : kNaN};
  const auto& r = c.reference_statistics;
  const double mean_scale = std::max(std::abs(r[kMean]), r[kStd]);
  const double scales[3] = {mean_scale, r[kStd] > 0 ? r[kStd] : mean_scale, r[kDel]};
  c.pass = true;
  for (std::size_t k = 0; k < (del ? 3u : 2u); ++k) {
    c.difference_percent[k] = difference_percent(r[k], c.test_statistics[k], scales[k]);
    // A NaN fails: the comparison below is false for it.
    c.pass = c.pass && std::abs(c.difference_percent[k]) <= percent;
  }
  if (!del) c.difference_percent[kDel] = kNaN;
}

void compare_samples(ChannelComparison& c, const std::vector<double>& ref, const std::vector<double>& test,
                     const std::vector<double>& time) {
  const ChannelTolerance& tol = c.tolerance;
  const Spread sr0 = spread(ref);
  const double atol = tol.atol + tol.range_atol * (sr0.max - sr0.min);
  c.worst_excess = -std::numeric_limits<double>::infinity();
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
  const Spread se = spread(error);
  c.rms_error_over_rms = sr0.rms > 0 ? se.rms / sr0.rms : kNaN;
  c.rms_error_over_range = sr0.max > sr0.min ? se.rms / (sr0.max - sr0.min) : kNaN;
  c.correlation = correlation(ref, test);
  c.pass = c.worst_excess <= 0.0;
}

}  // namespace

std::size_t ComparisonReport::passed() const {
  return static_cast<std::size_t>(std::count_if(channels.begin(), channels.end(), [](const ChannelComparison& c) { return c.pass; }));
}

bool ComparisonReport::pass() const {
  if (!required_missing.empty() || !refused.empty() || channels.empty()) return false;
  return passed() == channels.size();
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
  report.statistics_percent = options.statistics_percent;
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
  // A channel's column in a file: by its name, its alias from the options either way round, or
  // its built-in alias (MAP++'s T[1] for FAIRTEN1 and back).
  auto find_as = [&](const io::ChannelTable& table, const std::string& name) -> std::optional<std::size_t> {
    if (const auto i = table.find(name)) return i;
    if (const auto it = options.aliases.find(name); it != options.aliases.end()) return table.find(it->second);
    for (const auto& [a, b] : options.aliases)
      if (b == name) return table.find(a);
    if (const auto alias = builtin_alias(name)) {
      if (const auto i = table.find(alias->openfast)) return i;
      return table.find(alias->ours);
    }
    return std::nullopt;
  };
  if (!explicit_list)  // with --channels only those are reported
    for (std::size_t c = 1; c < test.names.size(); ++c) {
      if (!find_as(reference, test.names[c])) report.missing_in_reference.push_back(test.names[c]);
    }

  const std::vector<std::string> ref_names(reference.names.begin() + 1, reference.names.end());
  const std::vector<std::string> test_names(test.names.begin() + 1, test.names.end());
  std::vector<double> ref_values(rows.size()), test_values(rows.size());
  for (const std::string& name : wanted) {
    const auto rc = find_as(reference, name), tc = find_as(test, name);
    if (!rc || !tc) {
      if (explicit_list) {
        // Once, whichever file lacks it, with why (an alias, an OpenFAST channel we do not write, a typo).
        const std::string why = why_missing(name, !rc ? ref_names : test_names);
        const char* where = !rc && !tc ? "in neither file" : !rc ? "not in the reference" : "not in the test file";
        report.required_missing.push_back({name, why.empty() ? where : fmt::format("{}: {}", where, why)});
      } else {
        if (!tc) report.missing_in_test.push_back(name);
        if (!rc) report.missing_in_reference.push_back(name);
      }
      continue;
    }
    // OpenFAST marks a channel its configuration does not compute (ElastoDyn's blade outputs with
    // BeamDyn blades) with the unit INVALID: its values are not the quantity.
    const bool ref_invalid = normalised_unit(reference.units[*rc]) == "INVALID";
    if (ref_invalid || normalised_unit(test.units[*tc]) == "INVALID") {
      const char* file = ref_invalid ? "the reference" : "the test file";
      if (explicit_list)
        report.required_missing.push_back({name, fmt::format("{} marks it INVALID (not computed in that run)", file)});
      else
        report.invalid.push_back(name);
      continue;
    }
    const UnitMatch units = match_units(reference.units[*rc], test.units[*tc]);
    if (!units.comparable()) {
      report.refused.push_back({name, units.problem});
      continue;
    }
    for (std::size_t k = 0; k < rows.size(); ++k) {
      ref_values[k] = reference.columns[*rc][rows[k]];
      test_values[k] = units.factor * interpolate_linear(tt, test.columns[*tc], time[k]);
    }
    ChannelComparison c;
    c.name = name;
    if (test.names[*tc] != name) c.test_name = test.names[*tc];
    c.unit = normalised_unit(reference.units[*rc]);
    c.test_unit = normalised_unit(test.units[*tc]);
    c.unit_factor = units.factor;
    const auto it = options.tolerances.find(name);
    c.tolerance = it != options.tolerances.end() ? it->second : options.default_tolerance;
    c.constant_reference = *std::max_element(ref_values.begin(), ref_values.end()) ==
                           *std::min_element(ref_values.begin(), ref_values.end());
    if (options.statistics)
      compare_statistics(c, ref_values, test_values, time, options.statistics_percent, options.wohler_exponent);
    else
      compare_samples(c, ref_values, test_values, time);
    report.channels.push_back(std::move(c));
  }
  if (report.channels.empty() && report.required_missing.empty() && report.refused.empty()) {
    throw InputError({"compare", {}, "", "use --channels to pick channels present in both files"},
                     "the two files have no channel in common");
  }
  return report;
}

}  // namespace fowtsim::driver
