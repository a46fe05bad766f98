#pragma once
// `fowtsim post FILE… [options]` (issue 13): per file and channel the statistics, the DEL of every
// channel the fatigue configuration names, Welch spectra, proper orthogonal modes of nodal
// deflection channels and, with --lifetime, lifetime DELs over a wind-speed distribution. Reads our
// HDF5 and OpenFAST .out/.outb alike (io::read_channels), so the three give the same numbers for
// the same data. The library is fowtsim::post; this file only selects, loops and reports.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cli/post_results.hpp"

namespace fowtsim::driver {

struct PostOptions {
  std::vector<std::filesystem::path> files;         // run outputs (.h5, .out, .outb); from the spec with --lifetime
  std::vector<std::string> channels;                // channels to tabulate; empty = every channel but Time
  std::optional<post::TimeWindow> window;           // analysed window; none = whole record
  std::optional<std::filesystem::path> del_config;  // fatigue configuration (post_config.hpp)
  bool psd = false;                                 // spectra of the tabulated channels
  std::vector<std::string> psd_channels;            // spectra of these channels instead (implies psd)
  double segment_s = 100.0;                         // Welch segment length [s]; Δf = 1/segment_s
  std::string pom_pattern;                          // glob (* and ?) of nodal deflection channels; "" = no POMs
  bool pom_remove_means = false;                    // subtract node means before the SVD (the seed does not)
  post::ResidueCounting residue = post::ResidueCounting::half_cycles;
  std::vector<std::filesystem::path> outputs;       // .h5 and/or .csv files to write
  std::optional<std::filesystem::path> plot_dir;    // write PNGs there with tools/plot
  std::optional<std::filesystem::path> lifetime_spec;  // lifetime specification (post_config.hpp)
};

// Channels per file whose time series --plot stores and draws: the first of the tabulated ones.
inline constexpr std::size_t kPlotSeriesPerFile = 12;

// Computes everything the options ask for. Throws InputError for a bad file, channel or option.
PostResults analyse_post(const PostOptions& options, std::vector<PlotSeries>* plot_series = nullptr);

// analyse_post, then the tables on `out`, the files, the plots. Returns the exit code (0).
int run_post_command(const PostOptions& options, std::FILE* out);

// True when `name` matches the glob `pattern` (* any run of characters, ? one character).
bool glob_match(std::string_view pattern, std::string_view name);

}  // namespace fowtsim::driver
