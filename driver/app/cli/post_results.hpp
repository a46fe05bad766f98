#pragma once
// What `fowtsim post` computes, one struct per table, shared by the command (post_command.cpp),
// the screen/CSV table (post_table.cpp) and the HDF5 file (post_hdf5.cpp).
#include <optional>
#include <string>
#include <vector>

#include "fowtsim/post/lifetime.hpp"
#include "fowtsim/post/proper_orthogonal_modes.hpp"
#include "fowtsim/post/rainflow.hpp"
#include "fowtsim/post/statistics.hpp"
#include "fowtsim/post/welch_psd.hpp"

namespace fowtsim::driver {

struct ChannelFatigue {
  double wohler_exponent = 0.0;         // m, –
  std::optional<double> ultimate_load;  // L_ult (Goodman on), channel unit
  double goodman_fixed_mean = 0.0;      // L_MF, channel unit
  double damage_sum = 0.0;              // Σ nᵢ L_RFᵢ^m, channel unit^m
  double damage_equivalent_load = 0.0;  // DEL at f_eq, channel unit
};

// One row of the table: one channel of one file over the window.
struct PostRow {
  std::string file;                      // path as given
  std::string channel;                   // channel name
  std::string unit;                      // channel unit
  post::ChannelStatistics statistics;    // over the window
  double duration_s = 0.0;               // T = last − first time of the window [s]
  std::optional<ChannelFatigue> fatigue; // when the fatigue configuration gives the channel a DEL
};

struct ChannelSpectrum {
  std::string file, channel, unit;       // as in PostRow
  post::PowerSpectrum spectrum;          // Welch PSD, unit²/Hz
  std::vector<post::SpectralPeak> peaks; // highest first
};

struct FileModes {
  std::string file;                            // path as given
  std::vector<std::string> nodes;              // deflection channels, in table order (columns of X)
  std::string unit;                            // their unit
  std::vector<double> time_s;                  // window samples [s]
  post::ProperOrthogonalModes modes;           // SVD of the samples × nodes matrix
  std::vector<post::PowerSpectrum> mode_spectra;  // PSD of σᵢ aᵢ(t) for the first modes
};

struct LifetimeChannel {
  std::string channel, unit;  // channel name and unit
  double wohler_exponent = 0.0;  // m
  post::LifetimeLoad load;    // D_life, DEL_life
};

struct LifetimeRunRow {
  std::string file;             // run output
  double wind_speed_m_s = 0.0;  // mean speed of the run [m/s]
  double time_fraction = 0.0;   // f_j, –
  double duration_s = 0.0;      // T_j [s]
};

struct LifetimeResult {
  double design_life_years = 0.0;    // T_life [years]
  double equivalent_frequency_hz = 0.0;  // f_eq [Hz]
  std::string distribution;          // as the specification set it
  std::vector<LifetimeRunRow> runs;  // weights per run
  std::vector<LifetimeChannel> channels;  // one per channel with a DEL
};

// A windowed time series kept for the plots (--plot).
struct PlotSeries {
  std::string file, channel, unit;  // as in PostRow
  std::vector<double> time_s;       // window samples [s]
  std::vector<double> values;       // channel unit
};

struct PostResults {
  std::optional<post::TimeWindow> window;  // as requested
  post::ResidueCounting residue = post::ResidueCounting::half_cycles;
  double equivalent_frequency_hz = 1.0;    // f_eq of the DELs [Hz]
  std::vector<PostRow> rows;               // file-major, channels in table order
  std::vector<ChannelSpectrum> spectra;    // --psd
  std::vector<FileModes> modes;            // --pom
  std::optional<LifetimeResult> lifetime;  // --lifetime
};

}  // namespace fowtsim::driver
