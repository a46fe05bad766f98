#include "cli/screen_command.hpp"

#include <cmath>

#include <fmt/format.h>

#include "cli/hdf5_results.hpp"
#include "fowtsim/core/error.hpp"
#include "scenes/floating_screening.hpp"

namespace fowtsim::driver {
namespace {

void write_hdf5(const std::filesystem::path& path, const std::filesystem::path& deck, const ScreeningResult& r) {
  using namespace hdf5_results;
  io::hdf5::silence_error_printing();
  const io::hdf5::Handle file = created(H5Fcreate(path.string().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                                        path.string());
  write_doubles(file.get(), "frequency_hz", r.frequency_hz);
  write_doubles(file.get(), "wave_spectrum", r.wave_spectrum);
  write_doubles(file.get(), "wind_spectrum", r.wind_spectrum);
  write_strings(file.get(), "channels", r.outputs);
  write_strings(file.get(), "units", r.units);
  write_matrix(file.get(), "psd", r.psd);
  write_matrix(file.get(), "wave_rao_re", r.wave_rao.real());
  write_matrix(file.get(), "wave_rao_im", r.wave_rao.imag());
  write_matrix(file.get(), "wind_rao_re", r.wind_rao.real());
  write_matrix(file.get(), "wind_rao_im", r.wind_rao.imag());
  write_doubles(file.get(), "mean", r.mean);
  write_doubles(file.get(), "std_waves", r.std_waves);
  write_doubles(file.get(), "std_wind", r.std_wind);
  write_doubles(file.get(), "std_total", r.std_total);
  std::vector<double> frequency, damping;
  std::vector<std::string> dominant;
  for (const ScreeningMode& m : r.modes) {
    frequency.push_back(m.frequency_hz);
    damping.push_back(m.damping_ratio);
    dominant.push_back(m.dominant);
  }
  write_doubles(file.get(), "mode_frequency_hz", frequency);
  write_doubles(file.get(), "mode_damping_ratio", damping);
  write_strings(file.get(), "mode_dominant", dominant);
  Eigen::MatrixXd shapes(static_cast<Eigen::Index>(r.modes.size()), static_cast<Eigen::Index>(r.coordinates.size()));
  for (std::size_t k = 0; k < r.modes.size(); ++k) shapes.row(static_cast<Eigen::Index>(k)) = r.modes[k].shape.transpose();
  write_matrix(file.get(), "mode_shapes", shapes);
  write_strings(file.get(), "mode_coordinates", r.coordinates);
  attribute(file.get(), "deck", deck.string());
  attribute(file.get(), "region", r.operating_point.region);
  attribute(file.get(), "wind_speed_m_s", r.operating_point.wind_speed_m_s);
  attribute(file.get(), "hs_m", r.hs_m);
  attribute(file.get(), "tp_s", r.tp_s);
  attribute(file.get(), "sigma_u_m_s", r.sigma_u_m_s);
}

}  // namespace

int run_screen_command(const std::filesystem::path& deck, const std::vector<std::string>& settings,
                       const std::optional<std::filesystem::path>& output, std::FILE* out) {
  if (output && output->extension() != ".h5")
    throw InputError({"screen", std::nullopt, "-o", "a file name ending in .h5"},
                     fmt::format("-o {}: the screening is written as .h5", output->string()));
  const ScreeningResult r = screen_floating(deck, settings);
  const ScreeningOperatingPoint& op = r.operating_point;
  fmt::print(out, "{} — frequency-domain screening about the operating point (linear: no second-order waves, drag linearised)\n",
             deck.string());
  fmt::print(out, "operating point   {} at {:g} m/s: rotor {:.4g} rpm, pitch {:.4g}°, generator torque {:.5g} N·m; "
                  "platform surge {:.4g} m, heave {:.4g} m, pitch {:.4g}° ({} Newton iterations)\n",
             op.region, op.wind_speed_m_s, op.rotor_speed_rpm, op.pitch_deg, op.generator_torque_N_m, op.platform[0], op.platform[2],
             op.platform[4], op.newton_iterations);
  fmt::print(out, "sea and wind      Hs {:g} m, Tp {:g} s; turbulence σ_u {:.3g} m/s; drag linearised in {} iterations\n", r.hs_m,
             r.tp_s, r.sigma_u_m_s, r.drag_iterations);
  fmt::print(out, "\n{:>4} {:>11} {:>10} {:>9}  {}\n", "mode", "freq Hz", "period s", "damping", "dominant");
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    const ScreeningMode& m = r.modes[k];
    fmt::print(out, "{:>4} {:>11.5g} {:>10.4g} {:>9.4f}  {}\n", k + 1, m.frequency_hz, 1.0 / m.frequency_hz, m.damping_ratio, m.dominant);
  }
  fmt::print(out, "\n{:<11} {:>8} {:>12} {:>12} {:>12} {:>12}\n", "channel", "unit", "mean", "std waves", "std wind", "std");
  for (std::size_t i = 0; i < r.outputs.size(); ++i)
    fmt::print(out, "{:<11} {:>8} {:>12.5g} {:>12.5g} {:>12.5g} {:>12.5g}\n", r.outputs[i], r.units[i], r.mean[i], r.std_waves[i],
               r.std_wind[i], r.std_total[i]);
  fmt::print(out, "\ntime              {:.1f} ms: set-up {:.1f}, operating point {:.1f}, linearisation {:.1f}, "
                  "{} frequencies {:.1f}\n",
             1e3 * r.seconds_total(), 1e3 * r.seconds_set_up, 1e3 * r.seconds_operating_point, 1e3 * r.seconds_linearisation,
             r.frequency_hz.size(), 1e3 * r.seconds_solve);
  if (output) {
    write_hdf5(*output, deck, r);
    fmt::print(out, "written {}\n", output->string());
  }
  return 0;
}

}  // namespace fowtsim::driver
