#pragma once
// The load table of a sweep: one row per case — its state, factors, the statistics of the chosen
// channels over the analysis window and their short-term DELs — and the lifetime DEL of each
// fatigue channel over the wind-speed distribution (fowtsim::post: MLife's definitions). Failed,
// interrupted, running and missing cases keep their rows, with their state and reason.
#include <optional>
#include <string>
#include <vector>

#include "fowtsim/post/lifetime.hpp"
#include "fowtsim/post/statistics.hpp"
#include "sweep/case_expansion.hpp"
#include "sweep/case_outcome.hpp"
#include "sweep/sweep_spec.hpp"
#include "sweep/ultimate_loads.hpp"

namespace fowtsim::driver::sweep {

// The extreme of a channel in a case's analysis window, and what every table channel read then.
struct ChannelExtreme {
  double value = 0.0;               // channel unit
  double time_s = 0.0;              // [s]
  std::vector<double> concurrent;   // LoadTable::channels at time_s (NaN: not in the outputs)
};

struct LoadTableRow {
  const SweepCase* case_ = nullptr;  // the case (names, factors, seeds)
  CaseOutcome outcome;               // its state
  double window_s = 0.0;             // T of the DELs: last − first time in the window [s]
  std::vector<std::optional<post::ChannelStatistics>> statistics;  // per LoadTableSpec::channels
  std::vector<std::optional<double>> damage_equivalent_loads;      // per LoadTableSpec::fatigue
  std::vector<std::optional<double>> damage_sums;                  // per fatigue: Σ nᵢ L_RFᵢ^m
  std::vector<std::optional<ChannelExtreme>> maxima, minima;       // per LoadTableSpec::channels
};

struct LifetimeRow {
  FatigueChannel channel;              // channel and Wöhler exponent
  std::optional<post::LifetimeLoad> load;  // absent when no fatigue case completed
  std::size_t runs = 0;                // completed fatigue cases that entered it
};

struct LoadTable {
  std::string sweep_name;
  std::vector<std::string> group_names;        // load-case group names, by SweepCase::group
  double transient_s = 0.0, analysis_s = 0.0;  // window [transient, transient + analysis] [s]
  std::vector<std::string> channels;           // statistics channels, as LoadTableSpec::channels
  std::vector<std::string> units;              // their units (from the first completed case; "" if none)
  std::vector<FatigueChannel> fatigue;         // DEL columns
  std::vector<std::string> fatigue_units;      // their units
  std::vector<LoadTableRow> rows;              // one per case, in expansion order
  std::vector<LifetimeRow> lifetime;           // one per fatigue entry
  std::vector<UltimateLoad> ultimate;          // the ultimate-load table (ultimate_loads.hpp)
  post::WindSpeedDistribution wind_distribution;  // what weighted the lifetime DELs
  double bin_width_m_s = 0.0;                  // wind-speed bin of each fatigue speed [m/s]
  std::vector<std::string> notes;              // what the reader must know: channels missing, bins without runs
};

// Reads the outputs of every case (those not completed get their state only) and computes the table.
LoadTable build_load_table(const SweepSpec& spec, const std::vector<SweepCase>& cases, const std::vector<std::string>& deck_hashes,
                           const SweepLayout& layout);

// Fills table.lifetime from the rows' damage sums (table.rows, wind_distribution and bin_width_m_s
// set): each fatigue group weighted by its time fraction or its events a year (load_table.cpp).
void add_lifetime(LoadTable& table, const SweepSpec& spec);

// Writes BASE.csv, BASE_ultimate.csv, BASE.md and BASE.h5 (layout.table_base()). Numbers are written in their
// shortest round-trip form, so equal tables give equal files.
void write_load_table(const LoadTable& table, const std::filesystem::path& base);

}  // namespace fowtsim::driver::sweep
