#include "cli/modes_command.hpp"

#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "cli/hdf5_results.hpp"
#include "fowtsim/core/error.hpp"
#include "scenes/floating_modes.hpp"

namespace fowtsim::driver {
namespace {

constexpr const char* kAbout = "linearised about its initial state, tower and blades at their static deflection (controller demands and radiation memory held)";

double period_of(const StructuralMode& m) { return m.frequency_hz > 0.0 ? 1.0 / m.frequency_hz : INFINITY; }

void write_csv(const std::filesystem::path& path, const ModesResult& r) {
  std::ofstream file(path);
  if (!file) throw InputError({"modes", std::nullopt, "-o", "a writable file"}, "cannot create " + path.string());
  file << "mode,frequency_hz,period_s,damping_ratio,dominant";
  for (const std::string& c : r.coordinates) file << ',' << c;
  file << '\n';
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    const StructuralMode& m = r.modes[k];
    file << fmt::format("{},{:.9g},{:.9g},{:.6g},{}", k + 1, m.frequency_hz, period_of(m), m.damping_ratio, m.dominant);
    for (Eigen::Index i = 0; i < m.shape.size(); ++i) file << fmt::format(",{:.6g}", m.shape[i]);
    file << '\n';
  }
}

void write_hdf5(const std::filesystem::path& path, const std::filesystem::path& deck, const ModesResult& r) {
  using namespace hdf5_results;
  io::hdf5::silence_error_printing();
  const io::hdf5::Handle file = created(H5Fcreate(path.string().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                                        path.string());
  std::vector<double> frequency, period, damping;
  std::vector<std::string> dominant;
  Eigen::MatrixXd shapes(static_cast<Eigen::Index>(r.modes.size()), static_cast<Eigen::Index>(r.coordinates.size()));
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    frequency.push_back(r.modes[k].frequency_hz);
    period.push_back(period_of(r.modes[k]));
    damping.push_back(r.modes[k].damping_ratio);
    dominant.push_back(r.modes[k].dominant);
    shapes.row(static_cast<Eigen::Index>(k)) = r.modes[k].shape.transpose();
  }
  write_doubles(file.get(), "frequency_hz", frequency);
  write_doubles(file.get(), "period_s", period);
  write_doubles(file.get(), "damping_ratio", damping);
  write_strings(file.get(), "dominant", dominant);
  write_strings(file.get(), "coordinates", r.coordinates);
  write_matrix(file.get(), "shapes", shapes);
  attribute(file.get(), "deck", deck.string());
  attribute(file.get(), "about", kAbout);
}

}  // namespace

int run_modes_command(const std::filesystem::path& deck, const std::vector<std::string>& settings,
                      const std::optional<std::filesystem::path>& output, std::FILE* out) {
  if (output && output->extension() != ".h5" && output->extension() != ".csv")
    throw InputError({"modes", std::nullopt, "-o", "a file name ending in .h5 or .csv"},
                     fmt::format("-o {}: the modes are written as .h5 or .csv", output->string()));
  const ModesResult r = floating_modes(deck, settings);
  fmt::print(out, "{} — {}\n", deck.string(), kAbout);
  fmt::print(out, "{:>4} {:>12} {:>10} {:>10}  {:<11} shape ({}; m and rad, largest 1)\n", "mode", "freq Hz", "period s",
             "damping", "dominant", fmt::join(r.coordinates, " "));
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    const StructuralMode& m = r.modes[k];
    std::string shape;
    for (Eigen::Index i = 0; i < m.shape.size(); ++i) shape += fmt::format(" {:+.3f}", m.shape[i]);
    fmt::print(out, "{:>4} {:>12.6g} {:>10.4g} {:>10.4f}  {:<11}{}\n", k + 1, m.frequency_hz, period_of(m), m.damping_ratio,
               m.dominant, shape);
  }
  if (output) {
    if (output->extension() == ".h5") write_hdf5(*output, deck, r);
    else write_csv(*output, r);
    fmt::print(out, "written {}\n", output->string());
  }
  return 0;
}

}  // namespace fowtsim::driver
