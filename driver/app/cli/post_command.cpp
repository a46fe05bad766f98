#include "cli/post_command.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>

#include <fmt/format.h>

#include "cli/post_config.hpp"
#include "cli/post_hdf5.hpp"
#include "cli/post_table.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/io/suggest.hpp"
#include "fowtsim/post/damage_equivalent_load.hpp"
#include "fowtsim/post/record_checks.hpp"

extern char** environ;

namespace fowtsim::driver {

namespace {

constexpr std::size_t kSpectralPeaks = 3;  // peaks listed per spectrum
constexpr std::size_t kModeSpectra = 6;    // modes whose PSD is computed

std::size_t column_of(const io::ChannelTable& table, const std::string& name, const std::string& file) {
  if (const auto c = table.find(name)) return *c;
  const std::string hint = io::did_you_mean(name, table.names, io::LetterCase::ignored);
  throw InputError({"post", std::nullopt, "--channels", hint}, fmt::format("{}: no channel `{}`", file, name));
}

std::span<const double> rows_of(const std::vector<double>& column, const post::RowRange& rows) {
  return std::span<const double>(column).subspan(rows.first, rows.size());
}

// One WelchEstimator per segment length: its window and FFT buffers serve all channels of that length.
class WelchEstimators {
 public:
  const post::WelchEstimator& for_length(std::size_t segment_samples) {
    std::unique_ptr<post::WelchEstimator>& e = estimators_[segment_samples];
    if (!e) e = std::make_unique<post::WelchEstimator>(segment_samples);
    return *e;
  }

 private:
  std::map<std::size_t, std::unique_ptr<post::WelchEstimator>> estimators_;
};

struct Analysis {
  const PostOptions& options;
  std::optional<FatigueConfig> fatigue;
  PostResults results;
  WelchEstimators welch;
  std::vector<PlotSeries>* plot_series;  // null unless --plot
  std::vector<double> durations_s;       // T of each file's window, in file order

  void file(const std::filesystem::path& path);
  void modes(const io::ChannelTable& table, const std::string& file, const post::RowRange& rows, double sample_rate_hz);
  void lifetime(const LifetimeSpec& spec);
};

// Appends the configured calculated channels to a file's table; a missing component is bad input
// naming the file, the channel and the configuration entry.
void add_calculated(io::ChannelTable& table, const std::vector<CalculatedChannel>& calculated, const std::string& file) {
  for (const CalculatedChannel& c : calculated) {
    const auto refuse = [&](const std::string& why, const std::string& wanted) {
      throw InputError({"post", std::nullopt, c.name, wanted}, fmt::format("{}: {} ({})", file, why, c.location));
    };
    if (table.find(c.name)) refuse(fmt::format("the calculated channel {} is already a channel of the file", c.name), "a new name");
    std::vector<std::size_t> parts;
    for (const std::string& component : c.components) {
      const std::optional<std::size_t> column = table.find(component);
      if (!column) refuse(fmt::format("no channel {} for the calculated channel {}", component, c.name), "a channel of every file");
      if (!parts.empty() && table.units[*column] != table.units[parts.front()])
        refuse(fmt::format("the calculated channel {} adds {} [{}] to {} [{}]", c.name, component, table.units[*column],
                           table.names[parts.front()], table.units[parts.front()]),
               "components of one unit");
      parts.push_back(*column);
    }
    std::vector<double> magnitude(table.rows(), 0.0);
    for (const std::size_t p : parts)
      for (std::size_t r = 0; r < magnitude.size(); ++r) magnitude[r] += table.columns[p][r] * table.columns[p][r];
    for (double& m : magnitude) m = std::sqrt(m);
    table.names.push_back(c.name);
    table.units.push_back(table.units[parts.front()]);
    table.columns.push_back(std::move(magnitude));
  }
}

void Analysis::file(const std::filesystem::path& path) {
  const std::string name = path.string();
  io::ChannelTable table = io::read_channels(path);
  for (const std::string& warning : io::reading_warnings(table, name)) fmt::print(stderr, "warning: {}\n", warning);
  if (fatigue) add_calculated(table, fatigue->calculated, name);
  post::check_time_order(table.time(), name);
  const post::RowRange rows = post::rows_in_window(table.time(), options.window);
  const std::span<const double> time = rows_of(table.time(), rows);
  const double duration_s = time.back() - time.front();
  durations_s.push_back(duration_s);

  std::vector<std::size_t> columns;
  if (options.channels.empty()) {
    for (std::size_t c = 1; c < table.names.size(); ++c) columns.push_back(c);
  } else {
    for (const std::string& channel : options.channels) columns.push_back(column_of(table, channel, name));
  }
  std::size_t series_stored = 0;
  for (const std::size_t c : columns) {
    const std::span<const double> values = rows_of(table.columns[c], rows);
    post::check_no_nan(time, values, rows.first, name, table.names[c]);
    PostRow row{name, table.names[c], table.units[c], post::channel_statistics(time, values), duration_s, std::nullopt};
    if (const std::optional<post::FatigueParams> params = fatigue ? fatigue->params_for(table.names[c]) : std::nullopt) {
      const std::vector<post::RainflowCycle> cycles = post::rainflow_cycles(values, options.residue);
      const double damage = post::damage_sum(cycles, *params);
      row.fatigue = ChannelFatigue{params->wohler_exponent, params->ultimate_load, params->goodman_fixed_mean, damage,
                                   post::damage_equivalent_load(cycles, duration_s, *params)};
    }
    results.rows.push_back(std::move(row));
    if (plot_series && series_stored++ < kPlotSeriesPerFile)
      plot_series->push_back({name, table.names[c], table.units[c], {time.begin(), time.end()}, {values.begin(), values.end()}});
  }

  const bool spectra = options.psd || !options.psd_channels.empty();
  const bool pom = !options.pom_pattern.empty();
  if (!spectra && !pom) return;
  const double sample_rate_hz = post::uniform_sample_rate_hz(time);
  if (spectra) {
    std::vector<std::size_t> psd_columns = columns;
    if (!options.psd_channels.empty()) {
      psd_columns.clear();
      for (const std::string& channel : options.psd_channels) psd_columns.push_back(column_of(table, channel, name));
    }
    const post::WelchEstimator& estimator = welch.for_length(post::segment_samples_for(options.segment_s, sample_rate_hz, time.size()));
    for (const std::size_t c : psd_columns) {
      post::PowerSpectrum spectrum = estimator.estimate(rows_of(table.columns[c], rows), sample_rate_hz);
      std::vector<post::SpectralPeak> peaks = post::spectral_peaks(spectrum, kSpectralPeaks);
      results.spectra.push_back({name, table.names[c], table.units[c], std::move(spectrum), std::move(peaks)});
    }
  }
  if (pom) modes(table, name, rows, sample_rate_hz);
}

void Analysis::modes(const io::ChannelTable& table, const std::string& file, const post::RowRange& rows, double sample_rate_hz) {
  std::vector<std::size_t> nodes;
  for (std::size_t c = 1; c < table.names.size(); ++c)
    if (glob_match(options.pom_pattern, table.names[c])) nodes.push_back(c);
  if (nodes.empty())
    throw InputError({"post", std::nullopt, "--pom", "the scene writes nodal deflections when asked; check the channel names"},
                     fmt::format("{}: no channel matches `{}`", file, options.pom_pattern));
  Eigen::MatrixXd deflections(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(nodes.size()));
  FileModes f;
  f.file = file;
  f.unit = table.units[nodes[0]];
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    f.nodes.push_back(table.names[nodes[k]]);
    deflections.col(static_cast<Eigen::Index>(k)) =
        Eigen::Map<const Eigen::VectorXd>(table.columns[nodes[k]].data() + rows.first, static_cast<Eigen::Index>(rows.size()));
  }
  const std::span<const double> time = rows_of(table.time(), rows);
  f.time_s.assign(time.begin(), time.end());
  f.modes = post::proper_orthogonal_modes(deflections, options.pom_remove_means);
  const post::WelchEstimator& estimator = welch.for_length(post::segment_samples_for(options.segment_s, sample_rate_hz, rows.size()));
  const auto shown = std::min<Eigen::Index>(f.modes.modal_amplitudes.cols(), kModeSpectra);
  for (Eigen::Index i = 0; i < shown; ++i) {
    const Eigen::VectorXd amplitude = f.modes.modal_amplitudes.col(i);
    f.mode_spectra.push_back(estimator.estimate(std::span<const double>(amplitude.data(), static_cast<std::size_t>(amplitude.size())), sample_rate_hz));
  }
  results.modes.push_back(std::move(f));
}

// MLife's lifetime extrapolation (post/lifetime.hpp) of every channel with a DEL; each such channel
// must be in every run.
void Analysis::lifetime(const LifetimeSpec& spec) {
  LifetimeResult life;
  life.design_life_years = spec.design_life_years;
  life.equivalent_frequency_hz = spec.fatigue.equivalent_frequency_hz;
  life.distribution = spec.distribution_text;
  std::vector<double> speeds;
  for (const LifetimeRunSpec& run : spec.runs) speeds.push_back(run.wind_speed_m_s);
  const std::vector<double> fractions = post::run_time_fractions(speeds, spec.distribution, spec.bin_width_m_s, spec.renormalise);

  std::map<std::string, std::vector<const PostRow*>> rows_by_channel;  // in run order
  std::vector<std::string> channel_order;
  for (const PostRow& row : results.rows) {
    if (!row.fatigue) continue;
    auto& rows = rows_by_channel[row.channel];
    if (rows.empty()) channel_order.push_back(row.channel);
    rows.push_back(&row);
  }
  for (std::size_t j = 0; j < spec.runs.size(); ++j) life.runs.push_back({spec.runs[j].file.string(), speeds[j], fractions[j], durations_s[j]});
  for (const std::string& channel : channel_order) {
    const std::vector<const PostRow*>& rows = rows_by_channel[channel];
    if (rows.size() != spec.runs.size())
      throw InputError({"post", std::nullopt, channel, "list the channel in --channels or give every run it"},
                       fmt::format("lifetime DEL of {}: the channel is in {} of the {} runs", channel, rows.size(), spec.runs.size()));
    std::vector<post::LifetimeRun> runs;
    for (std::size_t j = 0; j < rows.size(); ++j) runs.push_back({fractions[j], rows[j]->duration_s, rows[j]->fatigue->damage_sum});
    life.channels.push_back({channel, rows[0]->unit, rows[0]->fatigue->wohler_exponent,
                             post::lifetime_damage_equivalent_load(runs, rows[0]->fatigue->wohler_exponent,
                                                                   spec.design_life_years * post::seconds_per_year,
                                                                   spec.fatigue.equivalent_frequency_hz)});
  }
  results.lifetime = std::move(life);
}

// /usr/bin/python3 tools/plot post POST.h5 --out DIR (Debian's matplotlib; see tools/plot).
void run_plot_script(const std::filesystem::path& post_file, const std::filesystem::path& dir) {
  const std::string python = "/usr/bin/python3", script = std::string(FOWTSIM_TOOLS_DIR) + "/plot";
  std::vector<std::string> args{python, script, "post", post_file.string(), "--out", dir.string()};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
    throw InputError({"post", std::nullopt, "--plot", "install Debian's python3 and python3-matplotlib"}, "cannot start " + python);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw InputError({"post", std::nullopt, "--plot", "see the message of tools/plot above"},
                     fmt::format("tools/plot failed (exit status {}); the tables and {} are written", WIFEXITED(status) ? WEXITSTATUS(status) : -1,
                                 post_file.string()));
}

}  // namespace

bool glob_match(std::string_view pattern, std::string_view name) {
  // Iterative matcher with one backtrack point: the last * and where its match began.
  std::size_t p = 0, n = 0, star = std::string_view::npos, star_match = 0;
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
      ++p;
      ++n;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      star_match = n;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      n = ++star_match;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

PostResults analyse_post(const PostOptions& options, std::vector<PlotSeries>* plot_series) {
  if (!(options.segment_s > 0.0))
    throw InputError({"post", std::nullopt, "--segment", ""}, fmt::format("--segment {} s must be > 0", options.segment_s));
  if (options.window && !(options.window->end_s > options.window->start_s))
    throw InputError({"post", std::nullopt, "--window", ""},
                     fmt::format("--window {} {}: the end must come after the start", options.window->start_s, options.window->end_s));
  std::optional<LifetimeSpec> spec;
  PostOptions resolved = options;
  if (options.lifetime_spec) {
    if (!options.files.empty() || options.del_config)
      throw InputError({"post", std::nullopt, "--lifetime", "list the runs and the fatigue section in the specification"},
                       "--lifetime takes its files and fatigue configuration from the specification, not from the command line");
    spec = read_lifetime_spec(*options.lifetime_spec);
    resolved.files.clear();
    for (const LifetimeRunSpec& run : spec->runs) resolved.files.push_back(run.file);
  }
  if (resolved.files.empty()) throw InputError({"post", std::nullopt, "FILE", ""}, "no file to post-process");

  Analysis analysis{resolved, std::nullopt, {}, {}, plot_series, {}};
  if (spec) analysis.fatigue = spec->fatigue;
  if (options.del_config) analysis.fatigue = read_fatigue_config(*options.del_config);
  analysis.results.window = options.window;
  analysis.results.residue = options.residue;
  if (analysis.fatigue) analysis.results.equivalent_frequency_hz = analysis.fatigue->equivalent_frequency_hz;
  for (const std::filesystem::path& file : resolved.files) analysis.file(file);
  if (spec) analysis.lifetime(*spec);
  return std::move(analysis.results);
}

int run_post_command(const PostOptions& options, std::FILE* out) {
  for (const std::filesystem::path& o : options.outputs)
    if (o.extension() != ".h5" && o.extension() != ".csv")
      throw InputError({"post", std::nullopt, "-o", "name the output x.h5 or x.csv"}, fmt::format("-o {}: the extension must be .h5 or .csv", o.string()));
  const auto start = std::chrono::steady_clock::now();
  std::vector<PlotSeries> series;
  const PostResults results = analyse_post(options, options.plot_dir ? &series : nullptr);
  const double analysis_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  print_post_results(out, results);

  std::optional<std::filesystem::path> hdf5;
  for (const std::filesystem::path& o : options.outputs) {
    if (o.extension() == ".csv") {
      write_post_csv(o, results);
    } else {
      write_post_hdf5(o, results, series);
      hdf5 = o;
    }
  }
  if (options.plot_dir && !hdf5) {
    hdf5 = *options.plot_dir / "post.h5";  // the plots read an HDF5 file: write one beside them
    write_post_hdf5(*hdf5, results, series);
  }
  for (const std::filesystem::path& o : options.outputs) fmt::print(out, "  output           {}\n", o.string());
  fmt::print(out, "  analysis time    {:.3f} s for {} rows (reading the files included)\n", analysis_s, results.rows.size());
  if (options.plot_dir) {
    std::fflush(out);
    run_plot_script(*hdf5, *options.plot_dir);
    fmt::print(out, "  plots            {}\n", options.plot_dir->string());
  }
  return 0;
}

}  // namespace fowtsim::driver
