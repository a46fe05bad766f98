#pragma once
// Run a BeamDyn reference case with the MBBT beam and compare channels with BeamDyn's output:
// shared by `fowtsim verify beam-…` and the driver's verification tests.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "fowtsim/io/channel_table.hpp"

namespace fowtsim::driver {

struct BeamDynRun {
  io::ChannelTable ours;
  io::ChannelTable reference;
  double wall_s = 0.0;       // our run's time loop [s]
  double simulated_s = 0.0;  // simulated time [s]
};

// Runs driver_inp with `segments` finite volumes, writing `output_base`.out, and reads both files.
BeamDynRun run_beamdyn_reference(const std::filesystem::path& driver_inp, const std::filesystem::path& reference_out,
                                 int segments, const std::filesystem::path& output_base,
                                 const std::optional<std::string>& integrator = std::nullopt,
                                 const std::optional<int>& matrix_max_age = std::nullopt);

// Last-row value of a channel; throws Error if the channel is missing.
double final_value(const io::ChannelTable& table, std::string_view channel);

// Ours interpolated linearly to the reference times t ≥ t_from.
struct SignalComparison {
  double rms_difference_over_rms = 0.0;  // RMS(ours − ref) / RMS(ref) — seed Table 2.3's measure
  double std_difference_over_std = 0.0;  // std(ours − ref) / std(ref): for signals with a large mean
  double mean_ours = 0.0, mean_reference = 0.0;
  double std_ours = 0.0, std_reference = 0.0;
};
SignalComparison compare_signal(const BeamDynRun& run, std::string_view channel, double t_from);

}  // namespace fowtsim::driver
