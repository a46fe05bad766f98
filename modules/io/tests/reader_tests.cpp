// Tests of the channel readers: OpenFAST text (.out) and binary (.outb, all FileFmtIDs), dispatch,
// and the reference OpenFAST outputs in ../shared/reference.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/testing/skip.hpp"
#include "outb_test_writer.hpp"

namespace {

using fowtsim::io::ChannelTable;
using fowtsim::io::testing::OutbFormat;

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A table shaped like an OpenFAST run: oscillating, ramping, constant and large-offset channels.
ChannelTable synthetic_table(std::size_t rows) {
  ChannelTable table;
  table.names = {"Time", "PtfmPitch", "Azimuth", "Wind1VelX", "GenSpeed", "RootMyc1"};
  table.units = {"s", "deg", "deg", "m/s", "rpm", "kN-m"};
  table.columns.assign(table.names.size(), {});
  for (std::size_t i = 0; i < rows; ++i) {
    const double t = 0.05 * static_cast<double>(i);
    table.columns[0].push_back(t);
    table.columns[1].push_back(3.0 * std::sin(0.2 * t) - 0.5);
    table.columns[2].push_back(std::fmod(72.6 * t, 360.0));
    table.columns[3].push_back(11.4);                                // constant channel
    table.columns[4].push_back(1173.7 + 0.01 * std::cos(1.3 * t));   // small swing, big offset
    table.columns[5].push_back(-8.0e3 * std::exp(-0.05 * t) + 2.0e3);
  }
  return table;
}

double range_of(const std::vector<double>& v) {
  const auto [low, high] = std::minmax_element(v.begin(), v.end());
  return *high - *low;
}
double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (const double x : v) m = std::max(m, std::abs(x));
  return m;
}

// Worst error of an OpenFAST int16-packed channel (WrBinFAST): the packed count is
// NINT(ColScl*x + ColOff) with ColScl = 65535/range, so rounding costs at most half a count,
// range/131070 in value. Single precision adds up to three float32 roundings (half an ulp, 2^-24
// relative) of quantities of size ColScl*|x| counts: ColScl*min and IntMin - ColScl*min when ColOff
// is formed, and ColScl*x when the data are single precision; that is ≤ 3·2^-24·max|x| in value.
// Tolerance: range/65535 (twice the rounding bound) + 4·2^-24·max|x| (one rounding to spare). The
// second term is what matters for constant channels (ColScl = 65535/sqrt(eps32), range 0) and big
// offsets (GenSpeed ≈ 1174 ± 0.01). Measured on the reference aero_steady files: worst error 0.72
// of this tolerance (RtAeroCq, U25), 0.50 count on channels where the rounding term dominates.
double packing_tolerance(const std::vector<double>& column) {
  return range_of(column) / 65535.0 + 4.0 * std::ldexp(max_abs(column), -24);
}

std::vector<std::filesystem::path> files_under(const std::filesystem::path& dir, const std::string& ext) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ext) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("OpenFAST text reader handles the layouts and Fortran number spellings", "[unit]") {
  // Intent: free header (even a line starting with "Time"), tab- or space-delimited header, CRLF,
  // Fortran numbers (3-digit exponents without E, D exponents, leading +, NaN) and trailing
  // blank lines all parse; Time is normalised.
  const auto dir = fowtsim::testing::scratch_dir("text_reader_layouts");
  write_text(dir / "a.out",
             "\r\nPredictions were generated using a test\r\nTime series of nothing in particular\r\n\r\n"
             "Time\tRootFxr     \tTipDxr\r\n(s)\t(N)\t(m)\r\n"
             "  0.0000\t 1.50000000E+00\t-1.0-100\r\n"
             "  0.1000\t+2.5D+01\t NaN\r\n"
             "  0.2000\t 0.106653535E-13\t1.234567890123456789\r\n\r\n\r\n");
  const ChannelTable table = fowtsim::io::read_openfast_text(dir / "a.out");
  REQUIRE(table.names == std::vector<std::string>{"Time", "RootFxr", "TipDxr"});
  REQUIRE(table.units == std::vector<std::string>{"s", "N", "m"});
  REQUIRE(table.rows() == 3);
  CHECK(table.columns[0] == std::vector<double>{0.0, 0.1, 0.2});
  CHECK(table.columns[1][0] == 1.5);
  CHECK(table.columns[1][1] == 25.0);
  CHECK(table.columns[1][2] == 0.106653535e-13);
  CHECK(table.columns[2][0] == -1.0e-100);
  CHECK(std::isnan(table.columns[2][1]));
  CHECK(table.columns[2][2] == 1.234567890123456789);
  CHECK_THAT(table.description, Catch::Contains("Time series of nothing"));

  // Space-delimited variant, lower-case "time", underflowing exponent.
  write_text(dir / "b.out", "time  X\n(sec) (-)\n0 1.0E-400\n1 -2\n");
  const ChannelTable spaced = fowtsim::io::read_openfast_text(dir / "b.out");
  REQUIRE(spaced.names == std::vector<std::string>{"Time", "X"});
  REQUIRE(spaced.units == std::vector<std::string>{"s", "-"});
  CHECK(spaced.columns[1] == std::vector<double>{0.0, -2.0});
}

TEST_CASE("OpenFAST text reader reports bad content with file and line", "[unit]") {
  // Intent: an unparsable or short row, or a missing names/units line, is an InputError that
  // names the file and the line, so a user can open it there.
  const auto dir = fowtsim::testing::scratch_dir("text_reader_errors");
  write_text(dir / "bad.out", "header\nTime\tA\n(s)\t(m)\n0.0\t1.0\n0.1\t*********\n");
  REQUIRE_THROWS_AS(fowtsim::io::read_openfast_text(dir / "bad.out"), fowtsim::InputError);
  REQUIRE_THROWS_WITH(fowtsim::io::read_openfast_text(dir / "bad.out"),
                      Catch::Contains("bad.out:5:") && Catch::Contains("*********"));
  write_text(dir / "short.out", "Time\tA\tB\n(s)\t(m)\t(m)\n0.0\t1.0\t2.0\n0.1\t1.0\n");
  REQUIRE_THROWS_WITH(fowtsim::io::read_openfast_text(dir / "short.out"),
                      Catch::Contains("short.out:4:") && Catch::Contains("2 values"));
  write_text(dir / "nonames.out", "just text\n1 2 3\n");
  REQUIRE_THROWS_AS(fowtsim::io::read_openfast_text(dir / "nonames.out"), fowtsim::InputError);
  write_text(dir / "units.out", "Time\tA\n(s)\n0 1\n");
  REQUIRE_THROWS_WITH(fowtsim::io::read_openfast_text(dir / "units.out"), Catch::Contains("1 units"));
  REQUIRE_THROWS_AS(fowtsim::io::read_openfast_text(dir / "absent.out"), fowtsim::InputError);
  // A last row without a line end was cut, perhaps inside its last number ("1.5" of "1.5E+01"):
  // dropped with a warning (a killed run's file stays readable up to its last whole row).
  write_text(dir / "cut.out", "Time\tA\n(s)\t(m)\n0.0\t1.0\n0.1\t1.5");
  const fowtsim::io::ChannelTable cut = fowtsim::io::read_openfast_text(dir / "cut.out");
  CHECK(cut.rows() == 1);
  REQUIRE(cut.warnings.size() == 1);
  CHECK_THAT(cut.warnings.front(), Catch::Contains("cut.out:4:") && Catch::Contains("cut short"));
  std::filesystem::create_directories(dir / "folder.out");
  REQUIRE_THROWS_WITH(fowtsim::io::read_openfast_text(dir / "folder.out"), Catch::Contains("is a directory"));
}

TEST_CASE("OpenFAST binary reader reads all four FileFmtID variants", "[unit]") {
  // Intent: files laid out as WrBinFAST writes them (test writer) read back with the right names,
  // units, time and values: exact for the float64 format 3, within the int16 packing bound
  // (packing_tolerance) for 1, 2 and 4.
  const auto dir = fowtsim::testing::scratch_dir("outb_formats");
  const ChannelTable original = synthetic_table(401);
  for (const OutbFormat format : {OutbFormat::with_time, OutbFormat::without_time,
                                  OutbFormat::no_compress_without_time, OutbFormat::chan_len_in}) {
    const auto id = static_cast<int>(format);
    INFO("FileFmtID " << id);
    const auto path = dir / ("format" + std::to_string(id) + ".outb");
    fowtsim::io::testing::write_openfast_binary(path, original, format, "synthetic run");
    const ChannelTable table = fowtsim::io::read_openfast_binary(path);
    REQUIRE(table.names == original.names);
    REQUIRE(table.units == original.units);
    REQUIRE(table.description == "synthetic run");
    REQUIRE(table.rows() == original.rows());
    // Time: format 1 packs it to int32 over [-65536, 65535], a step of range/131071 (half of it at
    // most after NINT); the others rebuild TimeOut1 + i*TimeIncr, off by a few ulps of 20 s.
    const double time_tolerance =
        format == OutbFormat::with_time ? range_of(original.time()) / 131071.0 : 1e-12;
    for (std::size_t i = 0; i < table.rows(); ++i) {
      REQUIRE(std::abs(table.time()[i] - original.time()[i]) <= time_tolerance);
    }
    for (std::size_t c = 1; c < original.columns.size(); ++c) {
      INFO("channel " << original.names[c]);
      const double tolerance =
          format == OutbFormat::no_compress_without_time ? 0.0 : packing_tolerance(original.columns[c]);
      for (std::size_t i = 0; i < table.rows(); ++i) {
        REQUIRE(std::abs(table.columns[c][i] - original.columns[c][i]) <= tolerance);
      }
    }
  }
}

TEST_CASE("OpenFAST binary reader rejects truncated and foreign files", "[unit]") {
  // Intent: a short file or an unknown FileID is an InputError, never an out-of-bounds read.
  const auto dir = fowtsim::testing::scratch_dir("outb_errors");
  const auto path = dir / "full.outb";
  fowtsim::io::testing::write_openfast_binary(path, synthetic_table(50), OutbFormat::chan_len_in);
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  for (const std::size_t keep : {std::size_t{1}, std::size_t{30}, bytes.size() - 1}) {
    write_text(dir / "cut.outb", bytes.substr(0, keep));
    REQUIRE_THROWS_AS(fowtsim::io::read_openfast_binary(dir / "cut.outb"), fowtsim::InputError);
  }
  write_text(dir / "foreign.outb", std::string("\x07\x00rest of a file", 16));
  REQUIRE_THROWS_WITH(fowtsim::io::read_openfast_binary(dir / "foreign.outb"),
                      Catch::Contains("unknown FileID 7"));
}

TEST_CASE("read_channels dispatches on the file extension", "[unit]") {
  // Intent: .out/.outb/.h5 go to their readers (any letter case); anything else is an InputError.
  const auto dir = fowtsim::testing::scratch_dir("read_channels");
  write_text(dir / "a.OUT", "Time\tA\n(s)\t(m)\n0.0\t1.0\n");
  CHECK(fowtsim::io::read_channels(dir / "a.OUT").names == std::vector<std::string>{"Time", "A"});
  fowtsim::io::testing::write_openfast_binary(dir / "b.outb", synthetic_table(5), OutbFormat::without_time);
  CHECK(fowtsim::io::read_channels(dir / "b.outb").rows() == 5);
  write_text(dir / "c.csv", "Time,A\n");
  REQUIRE_THROWS_WITH(fowtsim::io::read_channels(dir / "c.csv"), Catch::Contains(".csv"));
}

TEST_CASE("Every reference OpenFAST .out file reads consistently", "[verification]") {
  // Intent: the text reader copes with the real outputs of OpenFAST and its module drivers
  // (r-test BeamDyn, openfast-runs/...): as many units as names, data rows, time strictly increasing.
  const auto reference = fowtsim::testing::shared_dir_or_skip() / "reference";
  const auto files = files_under(reference, ".out");
  REQUIRE_FALSE(files.empty());
  for (const auto& path : files) {
    INFO(path.string());
    const ChannelTable table = fowtsim::io::read_openfast_text(path);
    REQUIRE(table.names.size() > 1);
    REQUIRE(table.units.size() == table.names.size());
    REQUIRE(table.names.front() == "Time");
    REQUIRE(table.rows() > 0);
    const auto& time = table.time();
    for (std::size_t i = 1; i < time.size(); ++i) REQUIRE(time[i] > time[i - 1]);
  }
}

TEST_CASE("Reference .outb files match their .out siblings channel by channel", "[verification]") {
  // Intent: our .outb reader agrees with the text output OpenFAST wrote in the same run
  // (aero_steady, OutFileFmt = 3: both files from the same data).
  const auto runs = fowtsim::testing::shared_dir_or_skip() / "reference" / "openfast-runs" / "aero_steady";
  if (!std::filesystem::is_directory(runs)) fowtsim::testing::skip("no aero_steady runs in " + runs.string());
  const auto files = files_under(runs, ".outb");
  REQUIRE_FALSE(files.empty());
  for (const auto& binary_path : files) {
    auto text_path = binary_path;
    text_path.replace_extension(".out");
    INFO(binary_path.string());
    const ChannelTable binary = fowtsim::io::read_openfast_binary(binary_path);
    const ChannelTable text = fowtsim::io::read_openfast_text(text_path);
    REQUIRE(binary.names == text.names);
    REQUIRE(binary.units == text.units);
    REQUIRE(binary.rows() == text.rows());
    // Time: the .out prints it with 4 decimals (F10.4), so ±5e-5 s; the .outb rebuilds it exactly.
    for (std::size_t i = 0; i < text.rows(); ++i) {
      REQUIRE(std::abs(binary.time()[i] - text.time()[i]) <= 5e-5 + 1e-12);
    }
    for (std::size_t c = 1; c < text.names.size(); ++c) {
      INFO("channel " << text.names[c]);
      // The .outb packing bound (packing_tolerance, taken on the text values, which differ from the
      // packed data by less than the text rounding) plus the .out rounding: 9 significant digits,
      // ≤ 5e-9 relative, bounded by 1e-8·max|x|.
      const double tolerance = packing_tolerance(text.columns[c]) + 1e-8 * max_abs(text.columns[c]);
      for (std::size_t i = 0; i < text.rows(); ++i) {
        REQUIRE(std::abs(binary.columns[c][i] - text.columns[c][i]) <= tolerance);
      }
    }
  }
}
