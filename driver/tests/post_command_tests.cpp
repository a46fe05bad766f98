// `fowtsim post`: tables, files, configuration errors, lifetime DELs, POMs and plots on small
// synthetic runs, and identical results from .out, .outb and HDF5 holding the same data.
#include <hdf5.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "cli/post_command.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/io/deck.hpp"
#include "fowtsim/io/hdf5_writer.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/post/lifetime.hpp"
#include "fowtsim/testing/skip.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

// A run output with one column per channel, written as the scenes write theirs.
void write_run(const std::filesystem::path& path, const std::vector<std::string>& names, const std::vector<std::string>& units,
               const std::vector<double>& time_s, const std::vector<std::vector<double>>& columns) {
  io::Hdf5Writer writer(path);
  std::vector<ChannelInfo> channels;
  for (std::size_t c = 0; c < names.size(); ++c) channels.push_back({names[c], units[c], "", "test"});
  writer.begin(channels, io::RunMetadata{});
  std::vector<double> row(names.size());
  for (std::size_t i = 0; i < time_s.size(); ++i) {
    for (std::size_t c = 0; c < names.size(); ++c) row[c] = columns[c][i];
    writer.append(time_s[i], row);
  }
  writer.finish(io::RunEnd{0.0, "completed", time_s.back(), {}});
}

// mean + A cos(2π f t) at 64 samples per period over `periods` periods (both ends): f T full cycles
// of range 2A (see modules/post/tests/damage_equivalent_load_tests.cpp).
std::vector<double> cosine(double amplitude, double mean, int periods) {
  std::vector<double> v;
  for (int j = 0; j <= periods * 64; ++j) v.push_back(mean + amplitude * std::cos(2.0 * std::numbers::pi * (j % 64) / 64.0));
  return v;
}

std::vector<double> times(std::size_t n, double dt_s) {
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = static_cast<double>(i) * dt_s;
  return t;
}

void write_text(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

std::vector<std::string> lines_of(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// A 1-D float64 dataset of a post HDF5 file.
std::vector<double> read_dataset(const std::filesystem::path& h5, const char* name) {
  const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);
  const hid_t set = H5Dopen2(file, name, H5P_DEFAULT);
  REQUIRE(set >= 0);
  const hid_t space = H5Dget_space(set);
  std::vector<double> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Sclose(space);
  H5Dclose(set);
  H5Fclose(file);
  return values;
}

}  // namespace

TEST_CASE("post tabulates every file and channel, with the Goodman DEL of a sine", "[unit]") {
  // Two files of a cosine load (mean −30, A = 2 and 3, 0.5 Hz over 100 s, 64 samples per period) and
  // a second channel. Closed form (MLife): DEL = 2A (L_ult − |L_MF|)/(L_ult − |μ|) (f T/(f_eq T))^{1/m}.
  const auto dir = testing::scratch_dir("post_table");
  const std::vector<double> t = times(50 * 64 + 1, 1.0 / (0.5 * 64));
  for (const double a : {2.0, 3.0})
    write_run(dir / fmt::format("run_a{}.h5", a), {"Load", "Other"}, {"kN", "m"}, t, {cosine(a, -30.0, 50), cosine(1.0, 0.0, 50)});
  write_text(dir / "del.yaml", "channels:\n  Load: {wohler_exponent: 10, ultimate_load: 100}\n");
  PostOptions options;
  options.files = {dir / "run_a2.h5", dir / "run_a3.h5"};
  options.del_config = dir / "del.yaml";
  options.outputs = {dir / "post.csv", dir / "post.h5"};
  std::FILE* screen = std::tmpfile();
  REQUIRE(run_post_command(options, screen) == 0);
  std::fclose(screen);

  const PostResults results = analyse_post(options);
  REQUIRE(results.rows.size() == 4u);  // 2 files × 2 channels, file-major
  CHECK((results.rows[0].channel == "Load" && results.rows[1].channel == "Other" && !results.rows[1].fatigue));
  for (const std::size_t i : {0u, 2u}) {
    const double a = i == 0 ? 2.0 : 3.0;
    const double expected = 2.0 * a * 100.0 / (100.0 - 30.0) * std::pow(0.5, 1.0 / 10.0);
    // Round-off of the cycle means and the sum (measured 2e-16 relative in the module test); 2e-15.
    CHECK(results.rows[i].fatigue->damage_equivalent_load == Approx(expected).epsilon(2e-15));
    CHECK(results.rows[i].statistics.max == -30.0 + a);
  }
  const std::vector<std::string> csv = lines_of(dir / "post.csv");
  REQUIRE(csv.size() == 5u);  // header + one line per file × channel
  CHECK(csv[0].rfind("file,channel,unit,min,max,mean,std", 0) == 0);
  CHECK(csv[1].find("Load,kN,") != std::string::npos);
  const std::vector<double> dels = read_dataset(dir / "post.h5", "statistics/damage_equivalent_load");
  REQUIRE(dels.size() == 4u);
  CHECK(dels[0] == results.rows[0].fatigue->damage_equivalent_load);
  CHECK(std::isnan(dels[1]));  // no DEL for Other
}

TEST_CASE("a window, the residue option and a default fatigue entry act as documented", "[unit]") {
  const auto dir = testing::scratch_dir("post_options");
  const std::vector<double> t = times(50 * 64 + 1, 1.0 / 32.0);
  write_run(dir / "run.h5", {"Load"}, {"kN"}, t, {cosine(2.0, 0.0, 50)});
  write_text(dir / "del.yaml", "equivalent_frequency_hz: 0.5\nchannels:\n  default: {wohler_exponent: 3}\n");
  PostOptions options;
  options.files = {dir / "run.h5"};
  options.del_config = dir / "del.yaml";
  options.window = post::TimeWindow{10.0, 30.0};  // 10 whole periods from a peak to a peak
  const PostRow half = analyse_post(options).rows.at(0);
  CHECK(half.statistics.samples == 20u * 32u + 1u);
  CHECK(half.duration_s == 20.0);
  // 10 cycles of range 4 at f_eq 0.5 Hz over 20 s: DEL = 4 (10/10)^{1/3} = 4 (2e-15: round-off).
  CHECK(half.fatigue->damage_equivalent_load == Approx(4.0).epsilon(2e-15));
  options.residue = post::ResidueCounting::full_cycles;  // the residue A, −A, A counts 2 instead of 1 cycle
  CHECK(analyse_post(options).rows.at(0).fatigue->damage_equivalent_load == Approx(4.0 * std::cbrt(11.0 / 10.0)).epsilon(2e-15));
  options.channels = {"Laod"};
  CHECK_THROWS_WITH(analyse_post(options), Catch::Contains("no channel `Laod`") && Catch::Contains("Load"));
}

TEST_CASE("a calculated channel is the magnitude of its components, with their DEL", "[unit]") {
  // Fx = A cos, Fy = A sin: |F| = A exactly at every sample (a constant: no cycles, DEL 0), and
  // Fx alone keeps its own DEL; a component missing from a file names file, channel and entry.
  const auto dir = testing::scratch_dir("post_calculated");
  const std::vector<double> t = times(50 * 64 + 1, 1.0 / 32.0);
  std::vector<double> fy;
  for (std::size_t j = 0; j < t.size(); ++j) fy.push_back(3.0 * std::sin(2.0 * std::numbers::pi * static_cast<double>(j % 64) / 64.0));
  write_run(dir / "run.h5", {"Fx", "Fy"}, {"kN", "kN"}, t, {cosine(3.0, 0.0, 50), fy});
  write_text(dir / "del.yaml", "calculated:\n  Fxy: {magnitude_of: [Fx, Fy]}\nchannels:\n  default: {wohler_exponent: 10}\n");
  PostOptions options;
  options.files = {dir / "run.h5"};
  options.del_config = dir / "del.yaml";
  const PostResults results = analyse_post(options);
  REQUIRE(results.rows.size() == 3u);
  const PostRow& magnitude = results.rows[2];
  CHECK(magnitude.channel == "Fxy");
  CHECK(magnitude.unit == "kN");
  CHECK(magnitude.statistics.mean == Approx(3.0).epsilon(1e-15));  // cos² + sin² = 1 to rounding
  CHECK(magnitude.statistics.max - magnitude.statistics.min < 1e-14);
  CHECK(results.rows[0].fatigue->damage_equivalent_load > 5.0);  // Fx: 50 cycles of range 6
  write_text(dir / "del.yaml", "calculated:\n  Fxz: {magnitude_of: [Fx, Fz]}\nchannels:\n  default: {wohler_exponent: 10}\n");
  CHECK_THROWS_WITH(analyse_post(options), Catch::Contains("run.h5") && Catch::Contains("no channel Fz") &&
                                               Catch::Contains("del.yaml:2"));
  // A name the file already has, and components of different units, are refused too.
  write_run(dir / "mixed.h5", {"Fx", "Mx"}, {"kN", "kN-m"}, t, {cosine(3.0, 0.0, 50), fy});
  options.files = {dir / "mixed.h5"};
  write_text(dir / "del.yaml", "calculated:\n  Fx: {magnitude_of: [Fx, Mx]}\nchannels:\n  default: {wohler_exponent: 10}\n");
  CHECK_THROWS_WITH(analyse_post(options), Catch::Contains("already a channel"));
  write_text(dir / "del.yaml", "calculated:\n  FM: {magnitude_of: [Fx, Mx]}\nchannels:\n  default: {wohler_exponent: 10}\n");
  CHECK_THROWS_WITH(analyse_post(options), Catch::Contains("kN-m") && Catch::Contains("del.yaml:2"));
}

TEST_CASE("a fatigue configuration with a misspelt key is refused with its file and line", "[unit]") {
  const auto dir = testing::scratch_dir("post_bad_config");
  write_text(dir / "del.yaml", "channels:\n  RootMyc1:\n    wohler_exponet: 10\n");
  write_run(dir / "run.h5", {"RootMyc1"}, {"kN-m"}, times(3, 1.0), {{1.0, 2.0, 1.0}});
  PostOptions options;
  options.files = {dir / "run.h5"};
  options.del_config = dir / "del.yaml";
  CHECK_THROWS_WITH(analyse_post(options), Catch::Contains("del.yaml:3:5") && Catch::Contains("wohler_exponent"));
  write_text(dir / "del.yaml", "channels:\n  RootMyc1: {wohler_exponent: 10, ultimate_load: 5, goodman_fixed_mean: 6}\n");
  CHECK_THROWS_WITH(analyse_post(options), Catch::Contains("del.yaml:2:") && Catch::Contains("goodman_fixed_mean"));
}

TEST_CASE("lifetime DELs from a specification equal the MLife extrapolation by hand", "[unit]") {
  // Runs at 8 m/s (A = 1, 100 s) and 12 m/s (A = 2, 50 s) of 0.5 Hz cosines; Rayleigh V_ave 10 m/s;
  // bins 4 m/s; m = 4. Each run's damage sum is f T (2A)^m; DEL_life = (Σ_j f_j/T_j D_j / f_eq)^{1/m}
  // with f_j = exp(−π/4 (v₋/10)²) − exp(−π/4 (v₊/10)²) (IEC 61400-1 Rayleigh).
  const auto dir = testing::scratch_dir("post_lifetime");
  write_run(dir / "u08.h5", {"Load"}, {"kN"}, times(50 * 64 + 1, 1.0 / 32.0), {cosine(1.0, 0.0, 50)});
  write_run(dir / "u12.h5", {"Load"}, {"kN"}, times(25 * 64 + 1, 1.0 / 32.0), {cosine(2.0, 0.0, 25)});
  write_text(dir / "life.yaml", R"(design_life_years: 20
bin_width_m_s: 4
wind_distribution: {model: rayleigh, iec_class: 1}
runs:
  - {file: u08.h5, wind_speed_m_s: 8}
  - {file: u12.h5, wind_speed_m_s: 12}
fatigue:
  channels: {Load: {wohler_exponent: 4}}
)");
  PostOptions options;
  options.lifetime_spec = dir / "life.yaml";
  options.outputs = {dir / "life.csv"};
  std::FILE* screen = std::tmpfile();
  REQUIRE(run_post_command(options, screen) == 0);
  std::fclose(screen);
  const PostResults results = analyse_post(options);
  REQUIRE(results.lifetime);
  const auto survival = [](double v) { return std::exp(-std::numbers::pi / 4.0 * (v / 10.0) * (v / 10.0)); };
  const double f8 = survival(6) - survival(10), f12 = survival(10) - survival(14);
  const double d8 = 50 * std::pow(2.0, 4), d12 = 25 * std::pow(4.0, 4);
  const double expected = std::pow(f8 / 100.0 * d8 + f12 / 50.0 * d12, 0.25);
  REQUIRE(results.lifetime->channels.size() == 1u);
  // Round-off only (the module test measures ≤ 4e-16); 2e-15.
  CHECK(results.lifetime->channels[0].load.damage_equivalent_load == Approx(expected).epsilon(2e-15));
  CHECK(results.lifetime->runs[1].time_fraction == Approx(f12).epsilon(2e-15));
  CHECK(results.lifetime->runs[1].duration_s == 50.0);
  CHECK(lines_of(dir / "life.lifetime.csv").size() == 2u);
  options.del_config = dir / "life.yaml";
  CHECK_THROWS_AS(analyse_post(options), InputError);  // the specification holds the fatigue section
}

TEST_CASE("post --pom recovers the modes of synthetic nodal deflections", "[unit]") {
  // Ten nodes moving as 3 a₁(t) φ₁ + a₂(t) φ₂ with orthonormal shapes and time histories (sines of 5
  // and 17 whole periods): singular value ratios 0.75 and 0.25 (seed 000 §4.6.4 definition).
  const auto dir = testing::scratch_dir("post_pom");
  const std::size_t samples = 400, nodes = 10;
  Eigen::VectorXd phi1(nodes), phi2(nodes);
  for (std::size_t i = 0; i < nodes; ++i) {
    phi1(static_cast<Eigen::Index>(i)) = std::pow((i + 1.0) / nodes, 2);
    phi2(static_cast<Eigen::Index>(i)) = std::sin(2.0 * std::numbers::pi * (i + 1.0) / nodes);
  }
  phi1.normalize();
  phi2 = (phi2 - phi2.dot(phi1) * phi1).normalized();
  std::vector<std::string> names, units;
  std::vector<std::vector<double>> columns(nodes + 1, std::vector<double>(samples));
  for (std::size_t i = 0; i < nodes; ++i) {
    names.push_back(fmt::format("B1N{:03d}TDxr", i + 1));
    units.push_back("m");
  }
  names.push_back("RotSpeed");
  units.push_back("rpm");
  const double norm = std::sqrt(samples / 2.0);
  for (std::size_t j = 0; j < samples; ++j) {
    const double a1 = std::sin(2.0 * std::numbers::pi * 5.0 * j / samples) / norm;
    const double a2 = std::sin(2.0 * std::numbers::pi * 17.0 * j / samples) / norm;
    for (std::size_t i = 0; i < nodes; ++i)
      columns[i][j] = 3.0 * a1 * phi1(static_cast<Eigen::Index>(i)) + a2 * phi2(static_cast<Eigen::Index>(i));
    columns[nodes][j] = 12.1;
  }
  write_run(dir / "run.h5", names, units, times(samples, 0.05), columns);
  PostOptions options;
  options.files = {dir / "run.h5"};
  options.pom_pattern = "B1N*TDxr";
  options.segment_s = 5.0;
  const PostResults results = analyse_post(options);
  REQUIRE(results.modes.size() == 1u);
  const post::ProperOrthogonalModes& m = results.modes[0].modes;
  CHECK(results.modes[0].nodes.size() == nodes);
  // 2e-14: round-off of the SVD (measured ≤ 1.7e-15 in the module test).
  CHECK(m.singular_value_ratios(0) == Approx(0.75).epsilon(2e-14));
  CHECK(m.singular_value_ratios(1) == Approx(0.25).epsilon(2e-14));
  CHECK(results.modes[0].mode_spectra.size() == 6u);
  // The first mode's PSD peaks at its 5 periods per 20 s = 0.25 Hz (Δf = 0.2 Hz at 5 s segments: the
  // nearest bin, 0.2 Hz).
  CHECK(post::spectral_peaks(results.modes[0].mode_spectra[0], 1)[0].frequency_hz == Approx(0.2).epsilon(1e-12));
  options.pom_pattern = "B2N*";
  CHECK_THROWS_AS(analyse_post(options), InputError);
}

TEST_CASE("glob patterns match * and ?", "[unit]") {
  CHECK(glob_match("B1N*TDxr", "B1N017TDxr"));
  CHECK_FALSE(glob_match("B1N*TDxr", "B1N017TDyr"));
  CHECK(glob_match("Root?yc*", "RootMyc1"));
  CHECK(glob_match("*", ""));
  CHECK_FALSE(glob_match("?", ""));
  CHECK(glob_match("a*b*c", "axxbyyc"));
}

TEST_CASE("an OpenFAST .out or .outb and our HDF5 holding the same data give identical results", "[verification]") {
  // The same numbers through the three readers must give bit-identical tables: the .out and .outb
  // of OpenFAST's steady 12 m/s rotor (../shared/reference) are each copied into our HDF5 format and
  // post-processed both ways (statistics, DELs with m = 3, 10, spectra).
  const auto shared = testing::shared_dir_or_skip();
  const auto dir = testing::scratch_dir("post_formats");
  write_text(dir / "del.yaml", "channels:\n  default: {wohler_exponent: 10}\n  RotTorq: {wohler_exponent: 3}\n");
  for (const char* ext : {".out", ".outb"}) {
    const std::filesystem::path openfast = shared / "reference/openfast-runs/aero_steady/U12" / (std::string("aero_steady_U12") + ext);
    const io::ChannelTable table = io::read_channels(openfast);
    const std::vector<std::string> names(table.names.begin() + 1, table.names.end()), units(table.units.begin() + 1, table.units.end());
    const std::vector<std::vector<double>> columns(table.columns.begin() + 1, table.columns.end());
    const std::filesystem::path copy = dir / (std::string("copy") + (ext + 1) + ".h5");
    write_run(copy, names, units, table.time(), columns);
    PostOptions options;
    options.del_config = dir / "del.yaml";
    options.psd = true;
    options.segment_s = 5.0;
    options.files = {openfast};
    const PostResults from_openfast = analyse_post(options);
    options.files = {copy};
    const PostResults from_hdf5 = analyse_post(options);
    INFO(ext);
    REQUIRE(from_openfast.rows.size() == from_hdf5.rows.size());
    REQUIRE(from_openfast.rows.size() == names.size());
    for (std::size_t i = 0; i < from_hdf5.rows.size(); ++i) {
      const PostRow &a = from_openfast.rows[i], &b = from_hdf5.rows[i];
      INFO(a.channel);
      CHECK(a.channel == b.channel);
      CHECK(a.unit == b.unit);
      CHECK(a.statistics.mean == b.statistics.mean);  // exact: the same doubles in the same order
      CHECK(a.statistics.std == b.statistics.std);
      CHECK(a.statistics.kurtosis == b.statistics.kurtosis);
      CHECK(a.statistics.time_of_max_s == b.statistics.time_of_max_s);
      CHECK(a.fatigue->damage_equivalent_load == b.fatigue->damage_equivalent_load);
      CHECK(from_openfast.spectra[i].spectrum.density == from_hdf5.spectra[i].spectrum.density);
    }
  }
}

TEST_CASE("post --plot writes non-empty PNGs of series, spectra, modes and DELs", "[unit]") {
  // tools/plot runs with Debian's /usr/bin/python3; without matplotlib the test is skipped.
  if (std::system("/usr/bin/python3 -c 'import matplotlib, h5py, numpy' >/dev/null 2>&1") != 0)
    testing::skip("/usr/bin/python3 has no matplotlib (Debian python3-matplotlib) or h5py");
  const auto dir = testing::scratch_dir("post_plot");
  const std::vector<double> t = times(20 * 64 + 1, 1.0 / 32.0);
  std::vector<double> node1 = cosine(0.5, 1.0, 20), node2 = cosine(1.0, 2.0, 20);
  write_run(dir / "run.h5", {"Load", "B1N001TDxr", "B1N002TDxr"}, {"kN", "m", "m"}, t, {cosine(2.0, 5.0, 20), node1, node2});
  write_text(dir / "del.yaml", "channels:\n  Load: {wohler_exponent: 4}\n");
  PostOptions options;
  options.files = {dir / "run.h5"};
  options.del_config = dir / "del.yaml";
  options.psd_channels = {"Load"};
  options.segment_s = 10.0;
  options.pom_pattern = "B1N*";
  options.plot_dir = dir / "plots";
  std::FILE* screen = std::tmpfile();
  REQUIRE(run_post_command(options, screen) == 0);
  std::fclose(screen);
  for (const char* png : {"series_Load.png", "psd_Load.png", "pom_shapes_000.png", "pom_psd_000.png", "del_Load.png"}) {
    INFO(png);
    CHECK(std::filesystem::file_size(dir / "plots" / png) > 1000u);  // a PNG with content, not a header
  }
  CHECK(std::filesystem::exists(dir / "plots/post.h5"));  // no -o .h5: the plots' input is written beside them
}
