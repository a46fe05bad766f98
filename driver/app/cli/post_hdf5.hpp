#pragma once
// `fowtsim post -o OUT.h5`: the results as HDF5, read by tools/plot (h5py: f["statistics/mean"][:]).
//
//   /statistics/   one 1-D dataset per column, one entry per file × channel: file, channel, unit
//                  (strings), min, max, mean, std, skewness, kurtosis, time_of_min_s, time_of_max_s,
//                  duration_s, samples, wohler_exponent, ultimate_load, goodman_fixed_mean,
//                  damage_sum, damage_equivalent_load (NaN where a channel has no DEL or no Goodman)
//     attrs        residue ("half" | "full"), equivalent_frequency_hz, window_start_s/window_end_s
//                  (when a window was given), moments ("population; kurtosis m4/m2^2, not excess")
//   /psd/NNN/      one group per file × channel: attrs file, channel, unit, segment_samples,
//                  segments; datasets frequency_hz, density (unit²/Hz), peak_frequency_hz, peak_density
//   /pom/NNN/      one group per file: attr file, unit; datasets nodes (strings), time_s,
//                  singular_values, singular_value_ratios, energy_fractions, node_means,
//                  shapes (nodes × modes), modal_amplitudes (samples × modes), mode_psd_frequency_hz,
//                  mode_psd_density (modes × bins)
//   /lifetime/     attrs design_life_years, equivalent_frequency_hz, distribution; datasets channel,
//                  unit, wohler_exponent, damage_sum, damage_equivalent_load; runs/ file,
//                  wind_speed_m_s, time_fraction, duration_s
//   /series/NNN/   (with --plot) attrs file, channel, unit; datasets time_s, values: the analysed
//                  window of the channels to plot
#include <filesystem>
#include <vector>

#include "cli/post_results.hpp"

namespace fowtsim::driver {

void write_post_hdf5(const std::filesystem::path& path, const PostResults& results, const std::vector<PlotSeries>& series);

}  // namespace fowtsim::driver
