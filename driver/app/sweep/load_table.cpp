#include "sweep/load_table.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/post/damage_equivalent_load.hpp"
#include "fowtsim/post/rainflow.hpp"

namespace fowtsim::driver::sweep {

namespace {

// Smallest spacing of the distinct fatigue wind speeds: bins that tile them without overlap.
double default_bin_width(const std::vector<SweepCase>& cases) {
  constexpr double kSingleSpeedBin_m_s = 2.0;  // IEC 61400-1 asks for wind-speed bins of at most 2 m/s
  std::set<double> speeds;
  for (const SweepCase& c : cases)
    if (c.fatigue && c.wind_speed_m_s) speeds.insert(*c.wind_speed_m_s);
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
  for (std::size_t k = 0; k < table.channels.size(); ++k)
    if (const auto values = column(table.channels[k], table.units[k])) row.statistics[k] = post::channel_statistics(time, *values);
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

void add_lifetime(LoadTable& table, const SweepSpec& spec) {
  std::vector<const LoadTableRow*> fatigue_rows;
  std::set<double> planned, covered;
  for (const LoadTableRow& row : table.rows) {
    if (!row.case_->fatigue || !row.case_->wind_speed_m_s) continue;
    planned.insert(*row.case_->wind_speed_m_s);
    if (row.outcome.state != CaseState::completed) continue;
    fatigue_rows.push_back(&row);
    covered.insert(*row.case_->wind_speed_m_s);
  }
  for (const double v : planned)
    if (!covered.contains(v))
      table.notes.push_back(fmt::format("no fatigue case at {} m/s completed: the time in its bin does no damage in the lifetime DELs", v));
  for (std::size_t k = 0; k < table.fatigue.size(); ++k) table.lifetime.push_back({table.fatigue[k], std::nullopt, 0});
  if (fatigue_rows.empty()) return;

  std::vector<double> speeds;
  for (const LoadTableRow* row : fatigue_rows) speeds.push_back(*row->case_->wind_speed_m_s);
  const std::vector<double> fractions = post::run_time_fractions(speeds, table.wind_distribution, table.bin_width_m_s);
  const double life_s = spec.load_table.design_life_years * post::seconds_per_year;
  for (std::size_t k = 0; k < table.fatigue.size(); ++k) {
    std::vector<post::LifetimeRun> runs;
    for (std::size_t j = 0; j < fatigue_rows.size(); ++j)
      if (fatigue_rows[j]->damage_sums[k]) runs.push_back({fractions[j], fatigue_rows[j]->window_s, *fatigue_rows[j]->damage_sums[k]});
    if (runs.empty()) continue;
    table.lifetime[k].runs = runs.size();
    table.lifetime[k].load = post::lifetime_damage_equivalent_load(runs, table.fatigue[k].wohler_exponent, life_s,
                                                                   spec.load_table.equivalent_frequency_hz);
  }
}

}  // namespace

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
  table.bin_width_m_s = spec.load_table.bin_width_m_s.value_or(default_bin_width(cases));

  for (std::size_t i = 0; i < cases.size(); ++i) {
    LoadTableRow row;
    row.case_ = &cases[i];
    row.outcome = read_case_outcome(layout, cases[i].name, deck_hashes[i]);
    row.statistics.resize(table.channels.size());
    row.damage_equivalent_loads.resize(table.fatigue.size());
    row.damage_sums.resize(table.fatigue.size());
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
  return table;
}

}  // namespace fowtsim::driver::sweep
