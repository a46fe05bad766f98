#include "cli/post_hdf5.hpp"

#include <hdf5.h>

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "cli/hdf5_results.hpp"
#include "fowtsim/io/hdf5_handle.hpp"

namespace fowtsim::driver {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using io::hdf5::Handle;
using namespace hdf5_results;

// A numbered group name that sorts in creation order: "000", "001", …
std::string numbered(std::size_t i) { return fmt::format("{:03d}", i); }

template <class Row, class Get>
std::vector<double> column(const std::vector<Row>& rows, Get get) {
  std::vector<double> c;
  c.reserve(rows.size());
  for (const Row& r : rows) c.push_back(get(r));
  return c;
}

template <class Row, class Get>
std::vector<std::string> text_column(const std::vector<Row>& rows, Get get) {
  std::vector<std::string> c;
  c.reserve(rows.size());
  for (const Row& r : rows) c.push_back(get(r));
  return c;
}

void write_statistics(hid_t file, const PostResults& results) {
  const Handle g = group(file, "statistics");
  const std::vector<PostRow>& rows = results.rows;
  write_strings(g.get(), "file", text_column(rows, [](const PostRow& r) { return r.file; }));
  write_strings(g.get(), "channel", text_column(rows, [](const PostRow& r) { return r.channel; }));
  write_strings(g.get(), "unit", text_column(rows, [](const PostRow& r) { return r.unit; }));
  write_doubles(g.get(), "min", column(rows, [](const PostRow& r) { return r.statistics.min; }));
  write_doubles(g.get(), "max", column(rows, [](const PostRow& r) { return r.statistics.max; }));
  write_doubles(g.get(), "mean", column(rows, [](const PostRow& r) { return r.statistics.mean; }));
  write_doubles(g.get(), "std", column(rows, [](const PostRow& r) { return r.statistics.std; }));
  write_doubles(g.get(), "skewness", column(rows, [](const PostRow& r) { return r.statistics.skewness; }));
  write_doubles(g.get(), "kurtosis", column(rows, [](const PostRow& r) { return r.statistics.kurtosis; }));
  write_doubles(g.get(), "time_of_min_s", column(rows, [](const PostRow& r) { return r.statistics.time_of_min_s; }));
  write_doubles(g.get(), "time_of_max_s", column(rows, [](const PostRow& r) { return r.statistics.time_of_max_s; }));
  write_doubles(g.get(), "duration_s", column(rows, [](const PostRow& r) { return r.duration_s; }));
  write_doubles(g.get(), "samples", column(rows, [](const PostRow& r) { return static_cast<double>(r.statistics.samples); }));
  const auto fatigue = [](auto get) { return [get](const PostRow& r) { return r.fatigue ? get(*r.fatigue) : kNaN; }; };
  write_doubles(g.get(), "wohler_exponent", column(rows, fatigue([](const ChannelFatigue& f) { return f.wohler_exponent; })));
  write_doubles(g.get(), "ultimate_load", column(rows, fatigue([](const ChannelFatigue& f) { return f.ultimate_load.value_or(kNaN); })));
  write_doubles(g.get(), "goodman_fixed_mean", column(rows, fatigue([](const ChannelFatigue& f) { return f.goodman_fixed_mean; })));
  write_doubles(g.get(), "damage_sum", column(rows, fatigue([](const ChannelFatigue& f) { return f.damage_sum; })));
  write_doubles(g.get(), "damage_equivalent_load", column(rows, fatigue([](const ChannelFatigue& f) { return f.damage_equivalent_load; })));
  attribute(g.get(), "residue", results.residue == post::ResidueCounting::half_cycles ? "half" : "full");
  attribute(g.get(), "equivalent_frequency_hz", results.equivalent_frequency_hz);
  attribute(g.get(), "moments", "population; kurtosis m4/m2^2, not excess");
  if (results.window) {
    attribute(g.get(), "window_start_s", results.window->start_s);
    attribute(g.get(), "window_end_s", results.window->end_s);
  }
}

void write_spectra(hid_t file, const std::vector<ChannelSpectrum>& spectra) {
  const Handle psd = group(file, "psd");
  for (std::size_t i = 0; i < spectra.size(); ++i) {
    const ChannelSpectrum& s = spectra[i];
    const Handle g = group(psd.get(), numbered(i));
    attribute(g.get(), "file", s.file);
    attribute(g.get(), "channel", s.channel);
    attribute(g.get(), "unit", s.unit);
    attribute(g.get(), "segment_samples", static_cast<double>(s.spectrum.segment_samples));
    attribute(g.get(), "segments", static_cast<double>(s.spectrum.segments));
    write_doubles(g.get(), "frequency_hz", s.spectrum.frequency_hz);
    write_doubles(g.get(), "density", s.spectrum.density);
    write_doubles(g.get(), "peak_frequency_hz", column(s.peaks, [](const post::SpectralPeak& p) { return p.frequency_hz; }));
    write_doubles(g.get(), "peak_density", column(s.peaks, [](const post::SpectralPeak& p) { return p.density; }));
  }
}

void write_modes(hid_t file, const std::vector<FileModes>& all_modes) {
  const Handle pom = group(file, "pom");
  for (std::size_t i = 0; i < all_modes.size(); ++i) {
    const FileModes& f = all_modes[i];
    const post::ProperOrthogonalModes& m = f.modes;
    const Handle g = group(pom.get(), numbered(i));
    attribute(g.get(), "file", f.file);
    attribute(g.get(), "unit", f.unit);
    write_strings(g.get(), "nodes", f.nodes);
    write_doubles(g.get(), "time_s", f.time_s);
    write_doubles(g.get(), "singular_values", m.singular_values.data(), {static_cast<hsize_t>(m.singular_values.size())});
    write_doubles(g.get(), "singular_value_ratios", m.singular_value_ratios.data(), {static_cast<hsize_t>(m.singular_value_ratios.size())});
    write_doubles(g.get(), "energy_fractions", m.energy_fractions.data(), {static_cast<hsize_t>(m.energy_fractions.size())});
    write_doubles(g.get(), "node_means", m.node_means.data(), {static_cast<hsize_t>(m.node_means.size())});
    write_matrix(g.get(), "shapes", m.shapes);
    write_matrix(g.get(), "modal_amplitudes", m.modal_amplitudes);
    if (f.mode_spectra.empty()) continue;
    Eigen::MatrixXd density(static_cast<Eigen::Index>(f.mode_spectra.size()), static_cast<Eigen::Index>(f.mode_spectra[0].density.size()));
    for (std::size_t k = 0; k < f.mode_spectra.size(); ++k)
      density.row(static_cast<Eigen::Index>(k)) = Eigen::Map<const Eigen::RowVectorXd>(f.mode_spectra[k].density.data(), density.cols());
    write_doubles(g.get(), "mode_psd_frequency_hz", f.mode_spectra[0].frequency_hz);
    write_matrix(g.get(), "mode_psd_density", density);
  }
}

void write_lifetime(hid_t file, const LifetimeResult& life) {
  const Handle g = group(file, "lifetime");
  attribute(g.get(), "design_life_years", life.design_life_years);
  attribute(g.get(), "equivalent_frequency_hz", life.equivalent_frequency_hz);
  attribute(g.get(), "distribution", life.distribution);
  write_strings(g.get(), "channel", text_column(life.channels, [](const LifetimeChannel& c) { return c.channel; }));
  write_strings(g.get(), "unit", text_column(life.channels, [](const LifetimeChannel& c) { return c.unit; }));
  write_doubles(g.get(), "wohler_exponent", column(life.channels, [](const LifetimeChannel& c) { return c.wohler_exponent; }));
  write_doubles(g.get(), "damage_sum", column(life.channels, [](const LifetimeChannel& c) { return c.load.damage_sum; }));
  write_doubles(g.get(), "damage_equivalent_load",
                column(life.channels, [](const LifetimeChannel& c) { return c.load.damage_equivalent_load; }));
  const Handle runs = group(g.get(), "runs");
  write_strings(runs.get(), "file", text_column(life.runs, [](const LifetimeRunRow& r) { return r.file; }));
  write_doubles(runs.get(), "wind_speed_m_s", column(life.runs, [](const LifetimeRunRow& r) { return r.wind_speed_m_s; }));
  write_doubles(runs.get(), "time_fraction", column(life.runs, [](const LifetimeRunRow& r) { return r.time_fraction; }));
  write_doubles(runs.get(), "duration_s", column(life.runs, [](const LifetimeRunRow& r) { return r.duration_s; }));
}

void write_series(hid_t file, const std::vector<PlotSeries>& series) {
  const Handle root = group(file, "series");
  for (std::size_t i = 0; i < series.size(); ++i) {
    const Handle g = group(root.get(), numbered(i));
    attribute(g.get(), "file", series[i].file);
    attribute(g.get(), "channel", series[i].channel);
    attribute(g.get(), "unit", series[i].unit);
    write_doubles(g.get(), "time_s", series[i].time_s);
    write_doubles(g.get(), "values", series[i].values);
  }
}

}  // namespace

void write_post_hdf5(const std::filesystem::path& path, const PostResults& results, const std::vector<PlotSeries>& series) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // our exceptions carry the context; HDF5 must not print
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  const Handle file = created(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, "file " + path.string());
  write_statistics(file.get(), results);
  if (!results.spectra.empty()) write_spectra(file.get(), results.spectra);
  if (!results.modes.empty()) write_modes(file.get(), results.modes);
  if (results.lifetime) write_lifetime(file.get(), *results.lifetime);
  if (!series.empty()) write_series(file.get(), series);
}

}  // namespace fowtsim::driver
