#include "sweep/load_table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/post/damage_equivalent_load.hpp"
#include "fowtsim/post/rainflow.hpp"

namespace fowtsim::driver::sweep {

namespace {

// Time-weighted fatigue cases: their group stands for a share of the design life split over wind-speed bins.
bool time_weighted(const SweepSpec& spec, const SweepCase& c) {
  return c.fatigue && c.wind_speed_m_s && spec.groups[c.group].events_per_year.empty();
}

// Smallest spacing of the distinct time-weighted fatigue wind speeds: bins that tile them without overlap.
double default_bin_width(const SweepSpec& spec, const std::vector<SweepCase>& cases) {
  constexpr double kSingleSpeedBin_m_s = 2.0;  // IEC 61400-1 asks for wind-speed bins of at most 2 m/s
  std::set<double> speeds;
  for (const SweepCase& c : cases)
    if (time_weighted(spec, c)) speeds.insert(*c.wind_speed_m_s);
  double width = kSingleSpeedBin_m_s;
  bool first_gap = true;
  for (auto it = speeds.begin(); it != speeds.end() && std::next(it) != speeds.end(); ++it) {
    const double gap = *std::next(it) - *it;
    width = first_gap ? gap : std::min(width, gap);
    first_gap = false;
  }
  return width;
}

void fill_row(LoadTable& table, LoadTableRow& row, const SweepSpec& spec, const std::filesystem::path& output) {
  const io::ChannelTable channels = io::read_hdf5_channels(output);
  const post::RowRange window = post::rows_in_window(
      channels.time(), post::TimeWindow{spec.transient_s, spec.transient_s + spec.analysis_s});
  const std::span<const double> time(channels.time().data() + window.first, window.size());
  row.window_s = time.back() - time.front();
  auto column = [&](const std::string& name, std::string& unit) -> std::optional<std::span<const double>> {
    const std::optional<std::size_t> c = channels.find(name);
    if (!c) {
      const std::string note = fmt::format("channel {} is not in the outputs (case {} first)", name, row.case_->name);
      if (std::none_of(table.notes.begin(), table.notes.end(), [&](const std::string& n) { return n.rfind("channel " + name + " ", 0) == 0; }))
        table.notes.push_back(note);
      return std::nullopt;
    }
    if (unit.empty()) unit = channels.units[*c];
    return std::span<const double>(channels.columns[*c].data() + window.first, window.size());
  };
  std::vector<std::optional<std::span<const double>>> columns;
  for (std::size_t k = 0; k < table.channels.size(); ++k) {
    columns.push_back(column(table.channels[k], table.units[k]));
    if (columns.back()) row.statistics[k] = post::channel_statistics(time, *columns.back());
  }
  // The extremes with their instants and the concurrent values (the first instant of a tie).
  auto extreme_at = [&](std::size_t i) {
    ChannelExtreme e{0.0, time[i], {}};
    for (const auto& c : columns) e.concurrent.push_back(c ? (*c)[i] : std::numeric_limits<double>::quiet_NaN());
    return e;
  };
  for (std::size_t k = 0; k < columns.size(); ++k) {
    if (!columns[k] || columns[k]->empty()) continue;
    const std::span<const double> v = *columns[k];
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    // minmax_element returns the last of equal maxima: take the first, as the minimum.
    const std::size_t i_max = static_cast<std::size_t>(std::find(v.begin(), v.end(), *hi) - v.begin());
    row.maxima[k] = extreme_at(i_max);
    row.maxima[k]->value = *hi;
    row.minima[k] = extreme_at(static_cast<std::size_t>(lo - v.begin()));
    row.minima[k]->value = *lo;
  }
  for (std::size_t k = 0; k < table.fatigue.size(); ++k) {
    const auto values = column(table.fatigue[k].channel, table.fatigue_units[k]);
    if (!values) continue;
    const std::vector<post::RainflowCycle> cycles = post::rainflow_cycles(*values);
    post::FatigueParams params;
    params.wohler_exponent = table.fatigue[k].wohler_exponent;
    params.equivalent_frequency_hz = spec.load_table.equivalent_frequency_hz;
    row.damage_sums[k] = post::damage_sum(cycles, params);
    row.damage_equivalent_loads[k] = post::damage_equivalent_load(cycles, row.window_s, params);
  }
}

// Lifetime damage over every fatigue group (MLife's extrapolation, fowtsim/post/lifetime.hpp), each
// run standing for its share of the design life:
//   time-weighted group (no events_per_year): f_j = fatigue_time_fraction × P(V in its bin) / runs in the bin;
//   event-weighted group (start-ups, shutdowns, faults): the run is one event, repeated
//     N_year(V) × T_life[years] / (runs at V) times, i.e. f_j = that count × T_j / T_life, with
//     N_year(V) listed per speed, or one total N shared as N P(bin of V) / Σ P(bins of the group).
}  // namespace

void add_lifetime(LoadTable& table, const SweepSpec& spec) {
  const double life_s = spec.load_table.design_life_years * post::seconds_per_year;
  std::vector<const LoadTableRow*> rows;
  std::vector<double> fractions;
  for (std::size_t gi = 0; gi < spec.groups.size(); ++gi) {
    const LoadCaseGroup& g = spec.groups[gi];
    if (!g.fatigue) continue;
    std::vector<const LoadTableRow*> group_rows;
    std::set<double> planned, covered;
    std::map<double, std::size_t> runs_at;
    for (const LoadTableRow& row : table.rows) {
      if (row.case_->group != gi || !row.case_->wind_speed_m_s) continue;
      planned.insert(*row.case_->wind_speed_m_s);
      if (row.outcome.state != CaseState::completed) continue;
      group_rows.push_back(&row);
      covered.insert(*row.case_->wind_speed_m_s);
      ++runs_at[*row.case_->wind_speed_m_s];
    }
    for (const double v : planned)
      if (!covered.contains(v))
        table.notes.push_back(fmt::format("no fatigue case of {} at {} m/s completed: {} no damage in the lifetime DELs", g.name, v,
                                          g.events_per_year.empty() ? "the time in its bin does" : "its events do"));
    if (group_rows.empty()) continue;
    if (g.events_per_year.empty()) {
      std::vector<double> speeds;
      for (const LoadTableRow* row : group_rows) speeds.push_back(*row->case_->wind_speed_m_s);
      const std::vector<double> f = post::run_time_fractions(speeds, table.wind_distribution, table.bin_width_m_s);
      for (std::size_t j = 0; j < group_rows.size(); ++j) {
        rows.push_back(group_rows[j]);
        fractions.push_back(g.fatigue_time_fraction * f[j]);
      }
      continue;
    }
    // One value: the events a year at any wind speed, shared by the group's speeds as the wind
    // distribution shares the time among their bins; a list: the events a year at each speed.
    double bins_probability = 0.0;
    auto bin_probability = [&](double v) {
      const double half = table.bin_width_m_s / 2.0;
      return table.wind_distribution.cumulative_probability(v + half) - table.wind_distribution.cumulative_probability(v - half);
    };
    for (const auto& [v, n] : runs_at) bins_probability += bin_probability(v);
    for (const LoadTableRow* row : group_rows) {
      const double v = *row->case_->wind_speed_m_s;
      double per_year = g.events_per_year.front() * bin_probability(v) / bins_probability;
      if (g.events_per_year.size() > 1)
        for (std::size_t i = 0; i < g.wind_speeds_m_s.size(); ++i)
          if (g.wind_speeds_m_s[i] == v) per_year = g.events_per_year[i];
      const double occurrences = per_year * spec.load_table.design_life_years / static_cast<double>(runs_at[v]);
      rows.push_back(row);
      fractions.push_back(occurrences * row->window_s / life_s);
    }
  }
  for (std::size_t k = 0; k < table.fatigue.size(); ++k) table.lifetime.push_back({table.fatigue[k], std::nullopt, 0});
  for (std::size_t k = 0; k < table.fatigue.size(); ++k) {
    std::vector<post::LifetimeRun> runs;
    for (std::size_t j = 0; j < rows.size(); ++j)
      if (rows[j]->damage_sums[k]) runs.push_back({fractions[j], rows[j]->window_s, *rows[j]->damage_sums[k]});
    if (runs.empty()) continue;
    table.lifetime[k].runs = runs.size();
    table.lifetime[k].load = post::lifetime_damage_equivalent_load(runs, table.fatigue[k].wohler_exponent, life_s,
                                                                   spec.load_table.equivalent_frequency_hz);
  }
}

LoadTable build_load_table(const SweepSpec& spec, const std::vector<SweepCase>& cases, const std::vector<std::string>& deck_hashes,
                           const SweepLayout& layout) {
  LoadTable table;
  table.sweep_name = spec.name;
  for (const LoadCaseGroup& g : spec.groups) table.group_names.push_back(g.name);
  table.transient_s = spec.transient_s;
  table.analysis_s = spec.analysis_s;
  table.channels = spec.load_table.channels;
  table.units.assign(table.channels.size(), "");
  table.fatigue = spec.load_table.fatigue;
  table.fatigue_units.assign(table.fatigue.size(), "");
  table.wind_distribution = post::WindSpeedDistribution::weibull_with_mean(
      spec.load_table.weibull_shape,
      spec.load_table.mean_wind_speed_m_s.value_or(post::iec_class_mean_speed_m_s(spec.turbine.wind_class)));
  table.bin_width_m_s = spec.load_table.bin_width_m_s.value_or(default_bin_width(spec, cases));

  for (std::size_t i = 0; i < cases.size(); ++i) {
    LoadTableRow row;
    row.case_ = &cases[i];
    row.outcome = read_case_outcome(layout, cases[i].name, deck_hashes[i]);
    row.statistics.resize(table.channels.size());
    row.damage_equivalent_loads.resize(table.fatigue.size());
    row.damage_sums.resize(table.fatigue.size());
    row.maxima.resize(table.channels.size());
    row.minima.resize(table.channels.size());
    if (row.outcome.state == CaseState::completed) {
      try {
        fill_row(table, row, spec, layout.output(cases[i].name));
      } catch (const Error& e) {
        // A completed file that cannot be analysed (too short for the window, unreadable) is a
        // failed case for the table, with the reason: never a silently empty row.
        row.outcome.state = CaseState::failed;
        row.outcome.message = std::string("cannot analyse the output: ") + e.what();
      }
    }
    table.rows.push_back(std::move(row));
  }
  add_lifetime(table, spec);
  table.ultimate = ultimate_loads(table, spec);
  return table;
}

}  // namespace fowtsim::driver::sweep
