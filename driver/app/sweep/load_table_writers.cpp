// The load table's three files: CSV (one row per case), HDF5 (one dataset per column, h5py:
// f["TwrBsMyt_DEL_m4"][:]) and a Markdown summary for people (failures first, lifetime DELs, then
// the cases). Columns are built once and shared by the CSV and the HDF5 file.
#include <hdf5.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/hdf5_handle.hpp"
#include "sweep/load_table.hpp"

namespace fowtsim::driver::sweep {

namespace {

using io::hdf5::Handle;

struct TextColumn {
  std::string name;
  std::function<std::string(const LoadTableRow&)> value;
};

struct NumberColumn {
  std::string name;  // also the HDF5 dataset name
  std::string unit;  // "" for dimensionless
  std::function<std::optional<double>(const LoadTableRow&)> value;
};

std::vector<TextColumn> text_columns(const LoadTable& t) {
  return {
      {"case", [](const LoadTableRow& r) { return r.case_->name; }},
      {"group", [&t](const LoadTableRow& r) { return t.group_names[r.case_->group]; }},
      {"state", [](const LoadTableRow& r) { return std::string(state_name(r.outcome.state)); }},
      {"exit_code", [](const LoadTableRow& r) { return r.outcome.exit_code ? std::to_string(*r.outcome.exit_code) : ""; }},
      {"message", [](const LoadTableRow& r) { return r.outcome.message; }},
  };
}

std::optional<double> as_number(const std::optional<std::uint64_t>& seed) {
  return seed ? std::optional<double>(static_cast<double>(*seed)) : std::nullopt;
}

std::vector<NumberColumn> number_columns(const LoadTable& t) {
  std::vector<NumberColumn> columns = {
      {"wind_speed_m_s", "m/s", [](const LoadTableRow& r) { return r.case_->wind_speed_m_s; }},
      {"realisation", "", [](const LoadTableRow& r) { return std::optional<double>(r.case_->realisation); }},
      {"wind_seed", "", [](const LoadTableRow& r) { return as_number(r.case_->wind_seed); }},
      {"wave_seed", "", [](const LoadTableRow& r) { return as_number(r.case_->wave_seed); }},
      {"hs_m", "m", [](const LoadTableRow& r) { return r.case_->hs_m; }},
      {"tp_s", "s", [](const LoadTableRow& r) { return r.case_->tp_s; }},
  };
  using Field = double post::ChannelStatistics::*;
  const std::pair<const char*, Field> fields[] = {{"min", &post::ChannelStatistics::min},
                                                  {"max", &post::ChannelStatistics::max},
                                                  {"mean", &post::ChannelStatistics::mean},
                                                  {"std", &post::ChannelStatistics::std}};
  for (std::size_t k = 0; k < t.channels.size(); ++k)
    for (const auto& [suffix, field] : fields)
      columns.push_back({t.channels[k] + "_" + suffix, t.units[k], [k, field](const LoadTableRow& r) -> std::optional<double> {
                           if (!r.statistics[k]) return std::nullopt;
                           return (*r.statistics[k]).*field;
                         }});
  for (std::size_t k = 0; k < t.fatigue.size(); ++k)
    columns.push_back({fmt::format("{}_DEL_m{}", t.fatigue[k].channel, t.fatigue[k].wohler_exponent), t.fatigue_units[k],
                       [k](const LoadTableRow& r) { return r.damage_equivalent_loads[k]; }});
  return columns;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return quoted + "\"";
}

// Shortest text that reads back as the same double: equal tables give equal files.
std::string number(const std::optional<double>& value) { return value ? fmt::format("{}", *value) : ""; }

void write_csv(const LoadTable& t, const std::filesystem::path& path) {
  const auto texts = text_columns(t);
  const auto numbers = number_columns(t);
  std::string out;
  for (const TextColumn& c : texts) out += (out.empty() ? "" : ",") + c.name;
  for (const NumberColumn& c : numbers) out += "," + csv_field(c.unit.empty() ? c.name : c.name + "[" + c.unit + "]");
  out += "\n";
  for (const LoadTableRow& r : t.rows) {
    for (std::size_t k = 0; k < texts.size(); ++k) out += (k ? "," : "") + csv_field(texts[k].value(r));
    for (const NumberColumn& c : numbers) out += "," + number(c.value(r));
    out += "\n";
  }
  std::ofstream(path, std::ios::binary | std::ios::trunc) << out;
}

std::string markdown_cell(const std::string& text) {
  std::string cell;
  for (const char c : text) cell += c == '|' ? std::string("\\|") : std::string(1, c == '\n' ? ' ' : c);
  return cell;
}

const char* sense_name(UltimateLoad::Sense sense) { return sense == UltimateLoad::Sense::maximum ? "max" : "min"; }

std::string rule_text(const UltimateLoad& u) {
  return fmt::format("{} of {}", u.mean_of_realisations ? "mean" : "largest", u.realisations);
}

// One row per channel and sense: the design value, its parts, where it governs and the concurrent values.
void write_ultimate_csv(const LoadTable& t, const std::filesystem::path& path) {
  std::string out = "channel,sense,unit,design_value,partial_safety_factor,characteristic_value,characteristic_rule,group,case,time_s";
  for (std::size_t k = 0; k < t.channels.size(); ++k)
    out += "," + csv_field(t.units[k].empty() ? t.channels[k] : t.channels[k] + "[" + t.units[k] + "]");
  out += "\n";
  for (const UltimateLoad& u : t.ultimate) {
    out += fmt::format("{},{},{},{},{},{},{},{},{},{}", csv_field(t.channels[u.channel]), sense_name(u.sense), csv_field(t.units[u.channel]),
                       number(u.design_value), number(u.partial_safety_factor), number(u.characteristic_value), rule_text(u),
                       csv_field(t.group_names[u.governing->case_->group]), csv_field(u.governing->case_->name), number(u.time_s));
    for (const double v : u.concurrent) out += "," + (std::isnan(v) ? std::string() : number(v));
    out += "\n";
  }
  std::ofstream(path, std::ios::binary | std::ios::trunc) << out;
}

void write_markdown(const LoadTable& t, const std::filesystem::path& path) {
  std::size_t completed = 0;
  for (const LoadTableRow& r : t.rows) completed += r.outcome.state == CaseState::completed;
  std::string md = fmt::format("# Load table of the sweep {}\n\n", t.sweep_name);
  md += fmt::format("{} cases, {} completed, {} not. Statistics and DELs over t = {} … {} s (the first {} s are the "
                    "transient, discarded). Files: load_table.csv, load_table.h5 (one column per quantity).\n\n",
                    t.rows.size(), completed, t.rows.size() - completed, t.transient_s, t.transient_s + t.analysis_s,
                    t.transient_s);
  if (completed < t.rows.size()) {
    md += "## Cases without results\n\n| case | state | exit code | reason |\n|---|---|---|---|\n";
    for (const LoadTableRow& r : t.rows)
      if (r.outcome.state != CaseState::completed)
        md += fmt::format("| {} | {} | {} | {} |\n", r.case_->name, state_name(r.outcome.state),
                          r.outcome.exit_code ? std::to_string(*r.outcome.exit_code) : "–", markdown_cell(r.outcome.message));
    md += "\n";
  }
  if (!t.lifetime.empty()) {
    md += fmt::format("## Lifetime damage-equivalent loads\n\nWind speed at hub height: Weibull k = {}, mean {:.4g} m/s; bins "
                      "of {} m/s around each fatigue speed (MLife's extrapolation, fowtsim/post/lifetime.hpp).\n\n"
                      "| channel | Wöhler m | DEL_life | unit | runs |\n|---|---|---|---|---|\n",
                      t.wind_distribution.shape_k, t.wind_distribution.mean_speed_m_s(), t.bin_width_m_s);
    for (const LifetimeRow& l : t.lifetime)
      md += fmt::format("| {} | {} | {} | {} | {} |\n", l.channel.channel, l.channel.wohler_exponent,
                        l.load ? fmt::format("{:.6g}", l.load->damage_equivalent_load) : "–",
                        t.fatigue_units[static_cast<std::size_t>(&l - t.lifetime.data())], l.runs);
    md += "\n";
  }
  if (!t.ultimate.empty()) {
    md += "## Ultimate loads\n\nDesign value γ_f F_k per channel and sense; F_k is the mean of a load case's realisations' "
          "extremes with at least six of them, else their largest (driver/app/sweep/ultimate_loads.hpp). The governing "
          "realisation, the time of its extreme and the concurrent values: load_table_ultimate.csv.\n\n"
          "| channel | sense | design γ_f F_k | γ_f | F_k | rule | governing group | case | t [s] | unit |\n"
          "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const UltimateLoad& u : t.ultimate)
      md += fmt::format("| {} | {} | {:.6g} | {} | {:.6g} | {} | {} | {} | {:.6g} | {} |\n", t.channels[u.channel], sense_name(u.sense),
                        u.design_value, u.partial_safety_factor, u.characteristic_value, rule_text(u), t.group_names[u.governing->case_->group],
                        u.governing->case_->name, u.time_s, t.units[u.channel]);
    md += "\n";
  }
  if (!t.notes.empty()) {
    md += "## Notes\n\n";
    for (const std::string& n : t.notes) md += "- " + n + "\n";
    md += "\n";
  }
  md += "## Cases\n\n| case | state | V [m/s] | Hs [m] | Tp [s] |";
  std::string rule = "|---|---|---|---|---|";
  for (std::size_t k = 0; k < t.channels.size(); ++k) {
    md += fmt::format(" {} mean / max [{}] |", t.channels[k], t.units[k]);
    rule += "---|";
  }
  for (std::size_t k = 0; k < t.fatigue.size(); ++k) {
    md += fmt::format(" {} DEL m={} [{}] |", t.fatigue[k].channel, t.fatigue[k].wohler_exponent, t.fatigue_units[k]);
    rule += "---|";
  }
  md += "\n" + rule + "\n";
  auto short_number = [](const std::optional<double>& v) { return v ? fmt::format("{:.4g}", *v) : std::string("–"); };
  for (const LoadTableRow& r : t.rows) {
    md += fmt::format("| {} | {} | {} | {} | {} |", r.case_->name, state_name(r.outcome.state), short_number(r.case_->wind_speed_m_s),
                      short_number(r.case_->hs_m), short_number(r.case_->tp_s));
    for (const auto& s : r.statistics)
      md += s ? fmt::format(" {:.4g} / {:.4g} |", s->mean, s->max) : std::string(" – |");
    for (const auto& del : r.damage_equivalent_loads) md += " " + short_number(del) + " |";
    md += "\n";
  }
  std::ofstream(path, std::ios::binary | std::ios::trunc) << md;
}

// ── HDF5 ──────────────────────────────────────────────────────────────────────────────────────

[[noreturn]] void hdf5_failure(const std::filesystem::path& path, const std::string& what) {
  throw Error({"sweep", std::nullopt, "load_table.h5", "check the output folder"}, "HDF5 failure on " + path.string() + ": " + what);
}

void string_attribute(hid_t object, const char* name, const std::string& value, const std::filesystem::path& path) {
  const Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  const Handle attribute(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  const char* text = value.c_str();
  if (!attribute.valid() || H5Awrite(attribute.get(), type.get(), &text) < 0) hdf5_failure(path, std::string("attribute ") + name);
}

void double_attribute(hid_t object, const char* name, double value, const std::filesystem::path& path) {
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  const Handle attribute(H5Acreate2(object, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attribute.valid() || H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, &value) < 0) hdf5_failure(path, std::string("attribute ") + name);
}

void number_dataset(hid_t file, const std::string& name, const std::vector<double>& values, const std::string& unit,
                    const std::filesystem::path& path) {
  const hsize_t n = values.size();
  const Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  const Handle dataset(H5Dcreate2(file, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  if (!dataset.valid() || (n > 0 && H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0))
    hdf5_failure(path, "dataset " + name);
  string_attribute(dataset.get(), "unit", unit, path);
}

void string_dataset(hid_t file, const std::string& name, const std::vector<std::string>& values, const std::filesystem::path& path) {
  const hsize_t n = values.size();
  const Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  const Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  const Handle dataset(H5Dcreate2(file, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  std::vector<const char*> text;
  for (const std::string& v : values) text.push_back(v.c_str());
  if (!dataset.valid() || (n > 0 && H5Dwrite(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()) < 0))
    hdf5_failure(path, "dataset " + name);
}

void write_hdf5(const LoadTable& t, const std::filesystem::path& path) {
  io::hdf5::silence_error_printing();  // failures are reported by the exceptions below
  const Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) hdf5_failure(path, "cannot create the file");
  string_attribute(file.get(), "sweep", t.sweep_name, path);
  double_attribute(file.get(), "transient_s", t.transient_s, path);
  double_attribute(file.get(), "analysis_s", t.analysis_s, path);
  constexpr double kAbsent = std::numeric_limits<double>::quiet_NaN();  // a case without this value
  for (const TextColumn& c : text_columns(t)) {
    std::vector<std::string> values;
    for (const LoadTableRow& r : t.rows) values.push_back(c.value(r));
    string_dataset(file.get(), c.name, values, path);
  }
  for (const NumberColumn& c : number_columns(t)) {
    std::vector<double> values;
    for (const LoadTableRow& r : t.rows) values.push_back(c.value(r).value_or(kAbsent));
    number_dataset(file.get(), c.name, values, c.unit, path);
  }
  std::vector<std::string> channels;
  std::vector<double> exponents, dels, damages, runs;
  for (std::size_t k = 0; k < t.lifetime.size(); ++k) {
    channels.push_back(t.lifetime[k].channel.channel);
    exponents.push_back(t.lifetime[k].channel.wohler_exponent);
    dels.push_back(t.lifetime[k].load ? t.lifetime[k].load->damage_equivalent_load : kAbsent);
    damages.push_back(t.lifetime[k].load ? t.lifetime[k].load->damage_sum : kAbsent);
    runs.push_back(static_cast<double>(t.lifetime[k].runs));
  }
  string_dataset(file.get(), "lifetime_channel", channels, path);
  number_dataset(file.get(), "lifetime_wohler_exponent", exponents, "", path);
  number_dataset(file.get(), "lifetime_DEL", dels, "channel unit", path);
  number_dataset(file.get(), "lifetime_damage_sum", damages, "channel unit^m", path);
  number_dataset(file.get(), "lifetime_runs", runs, "", path);
  std::vector<std::string> u_channel, u_sense, u_case;
  std::vector<double> u_design, u_gamma, u_characteristic, u_time;
  for (const UltimateLoad& u : t.ultimate) {
    u_channel.push_back(t.channels[u.channel]);
    u_sense.push_back(sense_name(u.sense));
    u_case.push_back(u.governing->case_->name);
    u_design.push_back(u.design_value);
    u_gamma.push_back(u.partial_safety_factor);
    u_characteristic.push_back(u.characteristic_value);
    u_time.push_back(u.time_s);
  }
  string_dataset(file.get(), "ultimate_channel", u_channel, path);
  string_dataset(file.get(), "ultimate_sense", u_sense, path);
  string_dataset(file.get(), "ultimate_case", u_case, path);
  number_dataset(file.get(), "ultimate_design_value", u_design, "channel unit", path);
  number_dataset(file.get(), "ultimate_partial_safety_factor", u_gamma, "", path);
  number_dataset(file.get(), "ultimate_characteristic_value", u_characteristic, "channel unit", path);
  number_dataset(file.get(), "ultimate_time_s", u_time, "s", path);
}

}  // namespace

void write_load_table(const LoadTable& table, const std::filesystem::path& base) {
  write_csv(table, base.string() + ".csv");
  write_ultimate_csv(table, base.string() + "_ultimate.csv");
  write_markdown(table, base.string() + ".md");
  write_hdf5(table, base.string() + ".h5");
}

}  // namespace fowtsim::driver::sweep
