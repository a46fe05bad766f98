#pragma once
// `fowtsim screen DECK [--set K=V …] [-o OUT.h5]`: the frequency-domain screening of a floating
// turbine deck (scenes/floating_screening.hpp) — its operating point, the natural frequencies and
// damping of the coupled closed-loop linear model, the standard deviations of the screened channels
// (waves, wind, both) and the time the case took — on the screen, and on request in OUT.h5:
//   frequency_hz, wave_spectrum (m²/Hz), wind_spectrum (rotor-effective, m²/s²/Hz), channels,
//   units (strings), psd (channels × frequencies, unit²/Hz), wave_rao_re/_im (per m of amplitude),
//   wind_rao_re/_im (per m/s), mean, std_waves, std_wind, std_total; mode_frequency_hz,
//   mode_damping_ratio, mode_dominant, mode_shapes (modes × mode_coordinates, m and rad, largest
//   entry 1); attributes deck, region, wind speed, Hs, Tp.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fowtsim::driver {

// Returns the exit code; InputError for a bad deck or an output that is not .h5.
int run_screen_command(const std::filesystem::path& deck, const std::vector<std::string>& settings,
                       const std::optional<std::filesystem::path>& output, std::FILE* out);

}  // namespace fowtsim::driver
