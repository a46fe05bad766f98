#include "cli/post_table.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

namespace {

// A table of text cells printed with each column as wide as its widest cell; numbers right-aligned.
class AlignedTable {
 public:
  explicit AlignedTable(std::vector<std::string> header) { rows_.push_back(std::move(header)); }
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  void print(std::FILE* out, std::size_t left_aligned_columns) const {
    std::vector<std::size_t> width(rows_[0].size(), 0);
    for (const auto& row : rows_)
      for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], display_width(row[c]));
    for (const auto& row : rows_) {
      std::string line;
      for (std::size_t c = 0; c < row.size(); ++c) {
        const std::string pad(width[c] - display_width(row[c]), ' ');
        line += c < left_aligned_columns ? row[c] + pad : pad + row[c];
        if (c + 1 < row.size()) line += "  ";
      }
      fmt::print(out, "  {}\n", line);
    }
  }

 private:
  // Characters, not bytes: UTF-8 continuation bytes take no column.
  static std::size_t display_width(const std::string& s) {
    return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
  }
  std::vector<std::vector<std::string>> rows_;
};

std::string number(double v) { return std::isnan(v) ? std::string("–") : fmt::format("{:.5g}", v); }
std::string exact(double v) { return std::isnan(v) ? std::string() : fmt::format("{:.17g}", v); }

// RFC 4180: a field holding a comma, quote or newline is quoted, quotes doubled.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string quoted = "\"";
  for (const char c : s) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

void print_statistics(std::FILE* out, const PostResults& results) {
  const bool any_fatigue = std::any_of(results.rows.begin(), results.rows.end(), [](const PostRow& r) { return r.fatigue.has_value(); });
  std::vector<std::string> header{"file", "channel", "unit", "min", "max", "mean", "std", "skew", "kurt", "t(min) s", "t(max) s"};
  if (any_fatigue) header.insert(header.end(), {"m", "L_ult", "DEL"});
  AlignedTable table(header);
  for (const PostRow& r : results.rows) {
    const post::ChannelStatistics& s = r.statistics;
    std::vector<std::string> row{r.file, r.channel, r.unit, number(s.min), number(s.max), number(s.mean), number(s.std),
                                 number(s.skewness), number(s.kurtosis), number(s.time_of_min_s), number(s.time_of_max_s)};
    if (any_fatigue) {
      if (r.fatigue)
        row.insert(row.end(), {number(r.fatigue->wohler_exponent), r.fatigue->ultimate_load ? number(*r.fatigue->ultimate_load) : "–",
                               number(r.fatigue->damage_equivalent_load)});
      else
        row.insert(row.end(), {"", "", ""});
    }
    table.add(std::move(row));
  }
  const std::string window = results.window ? fmt::format("{}–{} s", results.window->start_s, results.window->end_s) : "whole record";
  fmt::print(out, "── fowtsim post: statistics ({}; population moments, kurtosis not excess) ──\n", window);
  table.print(out, 3);
  if (any_fatigue)
    fmt::print(out, "  DEL: MLife, (Σ n·L_RF^m / (f_eq·T))^(1/m), f_eq {} Hz, residue as {} cycles, no binning; Goodman where L_ult is given\n",
               results.equivalent_frequency_hz, results.residue == post::ResidueCounting::half_cycles ? "half" : "full");
}

void print_spectra(std::FILE* out, const std::vector<ChannelSpectrum>& spectra) {
  if (spectra.empty()) return;
  AlignedTable table({"file", "channel", "unit", "Δf Hz", "segments", "peak 1 Hz", "peak 2 Hz", "peak 3 Hz", "PSD at peak 1"});
  for (const ChannelSpectrum& s : spectra) {
    std::vector<std::string> row{s.file, s.channel, s.unit + "²/Hz", number(s.spectrum.frequency_hz[1]), std::to_string(s.spectrum.segments)};
    for (std::size_t i = 0; i < 3; ++i) row.push_back(i < s.peaks.size() ? number(s.peaks[i].frequency_hz) : "");
    row.push_back(s.peaks.empty() ? "" : number(s.peaks[0].density));
    table.add(std::move(row));
  }
  fmt::print(out, "── spectra (Welch, Hann, 50 % overlap, one-sided) ──\n");
  table.print(out, 3);
}

void print_modes(std::FILE* out, const std::vector<FileModes>& all_modes) {
  for (const FileModes& f : all_modes) {
    const post::ProperOrthogonalModes& m = f.modes;
    fmt::print(out, "── proper orthogonal modes of {} ({} nodes {} … {}, {} samples{}) ──\n", f.file, f.nodes.size(), f.nodes.front(),
               f.nodes.back(), f.time_s.size(), m.node_means.isZero() ? "" : ", node means removed");
    AlignedTable table({"mode", "σ", "σ/Σσ %", "σ²/Σσ² %", "PSD peak Hz"});
    const Eigen::Index shown = std::min<Eigen::Index>(m.singular_values.size(), 6);
    for (Eigen::Index i = 0; i < shown; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const std::vector<post::SpectralPeak> peak = k < f.mode_spectra.size() ? post::spectral_peaks(f.mode_spectra[k], 1) : std::vector<post::SpectralPeak>{};
      table.add({std::to_string(i + 1), number(m.singular_values(i)), fmt::format("{:.2f}", 100 * m.singular_value_ratios(i)),
                 fmt::format("{:.2f}", 100 * m.energy_fractions(i)), peak.empty() ? "" : number(peak[0].frequency_hz)});
    }
    table.print(out, 1);
  }
}

void print_lifetime(std::FILE* out, const LifetimeResult& life) {
  fmt::print(out, "── lifetime ({} years, {}, f_eq {} Hz) ──\n", life.design_life_years, life.distribution, life.equivalent_frequency_hz);
  AlignedTable runs({"run", "V m/s", "f_j", "T_j s"});
  for (const LifetimeRunRow& r : life.runs)
    runs.add({r.file, number(r.wind_speed_m_s), fmt::format("{:.5f}", r.time_fraction), number(r.duration_s)});
  runs.print(out, 1);
  AlignedTable loads({"channel", "unit", "m", "lifetime DEL", "lifetime damage sum"});
  for (const LifetimeChannel& c : life.channels)
    loads.add({c.channel, c.unit, number(c.wohler_exponent), number(c.load.damage_equivalent_load), number(c.load.damage_sum)});
  loads.print(out, 2);
}

std::ofstream open_csv(const std::filesystem::path& path) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream csv(path);
  if (!csv) throw InputError({"post", std::nullopt, "-o", ""}, "cannot write " + path.string());
  return csv;
}

}  // namespace

void print_post_results(std::FILE* out, const PostResults& results) {
  print_statistics(out, results);
  print_spectra(out, results.spectra);
  print_modes(out, results.modes);
  if (results.lifetime) print_lifetime(out, *results.lifetime);
}

void write_post_csv(const std::filesystem::path& path, const PostResults& results) {
  std::ofstream csv = open_csv(path);
  csv << "file,channel,unit,min,max,mean,std,skewness,kurtosis,time_of_min_s,time_of_max_s,duration_s,samples,"
         "wohler_exponent,ultimate_load,goodman_fixed_mean,damage_equivalent_load\n";
  for (const PostRow& r : results.rows) {
    const post::ChannelStatistics& s = r.statistics;
    csv << csv_field(r.file) << ',' << csv_field(r.channel) << ',' << csv_field(r.unit);
    for (const double v : {s.min, s.max, s.mean, s.std, s.skewness, s.kurtosis, s.time_of_min_s, s.time_of_max_s, r.duration_s})
      csv << ',' << exact(v);
    csv << ',' << s.samples;
    if (r.fatigue)
      csv << ',' << exact(r.fatigue->wohler_exponent) << ',' << (r.fatigue->ultimate_load ? exact(*r.fatigue->ultimate_load) : "") << ','
          << exact(r.fatigue->goodman_fixed_mean) << ',' << exact(r.fatigue->damage_equivalent_load);
    else
      csv << ",,,,";
    csv << '\n';
  }
  if (!results.lifetime) return;
  std::filesystem::path lifetime_path = path;
  lifetime_path.replace_extension(".lifetime.csv");
  std::ofstream life = open_csv(lifetime_path);
  life << "channel,unit,wohler_exponent,lifetime_damage_equivalent_load,lifetime_damage_sum,design_life_years,equivalent_frequency_hz\n";
  for (const LifetimeChannel& c : results.lifetime->channels)
    life << csv_field(c.channel) << ',' << csv_field(c.unit) << ',' << exact(c.wohler_exponent) << ',' << exact(c.load.damage_equivalent_load)
         << ',' << exact(c.load.damage_sum) << ',' << exact(results.lifetime->design_life_years) << ','
         << exact(results.lifetime->equivalent_frequency_hz) << '\n';
}

}  // namespace fowtsim::driver
