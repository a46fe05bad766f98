#pragma once
// `fowtsim modes DECK [--set K=V …] [-o OUT.h5|OUT.csv]`: the table of a floating deck's modes
// (scenes/floating_modes.hpp) on the screen, and on request in a file:
//   .h5   frequency_hz, period_s, damping_ratio (one entry per mode), dominant, coordinates
//         (strings), shapes (modes × coordinates, m and rad, largest entry 1); attrs deck, about
//   .csv  one row per mode: mode, frequency_hz, period_s, damping_ratio, dominant, the shape
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fowtsim::driver {

// Returns the exit code; InputError for a bad deck or an output that is neither .h5 nor .csv.
int run_modes_command(const std::filesystem::path& deck, const std::vector<std::string>& settings,
                      const std::optional<std::filesystem::path>& output, std::FILE* out);

}  // namespace fowtsim::driver
