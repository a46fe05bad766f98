// Tests of the output sinks: HDF5 (round trip, metadata, crash safety) and OpenFAST-style text.
#include <hdf5.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/hdf5_handle.hpp"
#include "fowtsim/io/hdf5_writer.hpp"
#include "fowtsim/io/output_sink.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/io/text_out_writer.hpp"
#include "fowtsim/testing/skip.hpp"

namespace {

using fowtsim::ChannelInfo;
using fowtsim::io::ChannelTable;
using fowtsim::io::Hdf5Writer;
using fowtsim::io::RunEnd;
using fowtsim::io::RunMetadata;
using fowtsim::io::TextOutOptions;
using fowtsim::io::TextOutWriter;
using fowtsim::io::hdf5::Handle;

std::vector<ChannelInfo> test_channels() {
  return {{"PtfmSurge", "m", "platform surge, inertial X", "toy"},
          {"RotSpeed", "rpm", "rotor speed", "toy"},
          {"RootMyc1", "kN-m", "blade 1 flapwise root moment", "toy"}};
}

RunMetadata test_metadata() {
  RunMetadata metadata;
  metadata.version = "0.1.0";
  metadata.deck_path = "inputs/test.yaml";
  metadata.deck_hash = "0123abcd";
  metadata.seeds = {42, 18446744073709551615ULL};
  metadata.dt_s = 0.0025;
  metadata.dt_coupling_s = 0.0125;
  metadata.extra = {{"scene", "unit test"}};
  return metadata;
}

// Values with awkward bits (irrational fractions, signs, a wide exponent range) so "bit-exact"
// and "within precision" mean something.
std::vector<double> row_values(std::size_t row) {
  const double x = static_cast<double>(row);
  return {std::sin(0.1 * x) * 1.0e-3, 12.1 + std::cos(0.37 * x) / 3.0, -std::exp(0.01 * x) * 1.0e5};
}
double row_time(std::size_t row) { return 0.0125 * static_cast<double>(row); }

// --- small HDF5 helpers for checking attributes independently of read_hdf5_channels ---

std::optional<std::string> string_attribute(hid_t object, const char* name) {
  if (H5Aexists(object, name) <= 0) return std::nullopt;
  const Handle attribute{H5Aopen(object, name, H5P_DEFAULT), H5Aclose};
  const Handle type{H5Aget_type(attribute.get()), H5Tclose};
  // h5py returns str only for variable-length strings; insist on that and on UTF-8.
  REQUIRE(H5Tis_variable_str(type.get()) > 0);
  REQUIRE(H5Tget_cset(type.get()) == H5T_CSET_UTF8);
  char* text = nullptr;
  REQUIRE(H5Aread(attribute.get(), type.get(), &text) >= 0);
  std::string value(text);
  H5free_memory(text);
  return value;
}

double double_attribute(hid_t object, const char* name) {
  const Handle attribute{H5Aopen(object, name, H5P_DEFAULT), H5Aclose};
  REQUIRE(attribute.get() >= 0);
  double value = 0.0;
  REQUIRE(H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value) >= 0);
  return value;
}

std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("HDF5 output reads back bit-exactly over several chunks, with its metadata", "[unit]") {
  // Intent: what the writer appends is exactly what the reader returns (names, units, every bit of
  // every value, Time first and channels in declaration order), across full and partial blocks.
  const auto path = fowtsim::testing::scratch_dir("hdf5_round_trip") / "run.h5";
  constexpr std::size_t kRowsPerChunk = 64;
  constexpr std::size_t kRows = 1000;  // 15 full blocks and a partial one
  {
    Hdf5Writer writer(path, kRowsPerChunk);
    writer.begin(test_channels(), test_metadata());
    for (std::size_t i = 0; i < kRows; ++i) writer.append(row_time(i), row_values(i));
    REQUIRE(writer.rows_appended() == kRows);
    writer.finish(RunEnd{3.5, "completed", row_time(kRows - 1)});
  }

  const ChannelTable table = fowtsim::io::read_hdf5_channels(path);
  REQUIRE(table.names == std::vector<std::string>{"Time", "PtfmSurge", "RotSpeed", "RootMyc1"});
  REQUIRE(table.units == std::vector<std::string>{"s", "m", "rpm", "kN-m"});
  REQUIRE(table.rows() == kRows);
  for (std::size_t i = 0; i < kRows; ++i) {
    REQUIRE(table.time()[i] == row_time(i));  // bit-exact: float64 in, float64 out
    const auto expected = row_values(i);
    for (std::size_t c = 0; c < expected.size(); ++c) REQUIRE(table.columns[c + 1][i] == expected[c]);
  }
  REQUIRE(table.find("RotSpeed") == std::optional<std::size_t>(2));
  REQUIRE_FALSE(table.find("GenPwr").has_value());

  const Handle file{H5Fopen(path.string().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
  REQUIRE(file.get() >= 0);
  CHECK(string_attribute(file.get(), "version") == "0.1.0");
  CHECK(string_attribute(file.get(), "deck_path") == "inputs/test.yaml");
  CHECK(string_attribute(file.get(), "deck_hash") == "0123abcd");
  CHECK(string_attribute(file.get(), "scene") == "unit test");
  CHECK(string_attribute(file.get(), "status") == "completed");
  CHECK(double_attribute(file.get(), "dt_s") == 0.0025);
  CHECK(double_attribute(file.get(), "dt_coupling_s") == 0.0125);
  CHECK(double_attribute(file.get(), "wall_time_s") == 3.5);
  CHECK(double_attribute(file.get(), "end_time_s") == row_time(kRows - 1));
  {
    const Handle seeds{H5Aopen(file.get(), "seeds", H5P_DEFAULT), H5Aclose};
    std::vector<std::uint64_t> values(2);
    REQUIRE(H5Aread(seeds.get(), H5T_NATIVE_UINT64, values.data()) >= 0);
    CHECK(values == test_metadata().seeds);
  }
  const Handle dataset{H5Dopen2(file.get(), "RootMyc1", H5P_DEFAULT), H5Dclose};
  CHECK(string_attribute(dataset.get(), "unit") == "kN-m");
  CHECK(string_attribute(dataset.get(), "description") == "blade 1 flapwise root moment");
  CHECK(string_attribute(dataset.get(), "module") == "toy");
}

TEST_CASE("HDF5 output survives a run that dies by exception", "[unit]") {
  // Intent: a writer destroyed during stack unwinding keeps every appended row (also those still
  // buffered) and leaves a status that is not "completed".
  const auto path = fowtsim::testing::scratch_dir("hdf5_exception") / "run.h5";
  constexpr std::size_t kRows = 150;  // two full blocks of 64 and 22 rows still buffered
  try {
    Hdf5Writer writer(path, 64);
    writer.begin(test_channels(), test_metadata());
    for (std::size_t i = 0; i < kRows; ++i) writer.append(row_time(i), row_values(i));
    throw std::runtime_error("simulated divergence");
  } catch (const std::runtime_error&) {
  }
  const ChannelTable table = fowtsim::io::read_hdf5_channels(path);
  REQUIRE(table.rows() == kRows);
  REQUIRE(table.columns[3][kRows - 1] == row_values(kRows - 1)[2]);
  const Handle file{H5Fopen(path.string().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
  const auto status = string_attribute(file.get(), "status");
  REQUIRE(status.has_value());
  REQUIRE(*status != "completed");
}

TEST_CASE("HDF5 output of a killed process keeps every block written before the kill", "[unit]") {
  // Intent: crash safety without destructors. A child process appends 2.5 blocks (then, in the
  // second case, calls flush()) and ends with _Exit inside the writer's scope, as if killed: no
  // destructor, no finish. The file must open and hold every row flushed before the "kill".
  const auto dir = fowtsim::testing::scratch_dir("hdf5_killed");
  constexpr std::size_t kBlock = 64;
  constexpr std::size_t kAppended = 2 * kBlock + kBlock / 2;
  for (const bool explicit_flush : {false, true}) {
    const auto path = dir / (explicit_flush ? "flushed.h5" : "blocks_only.h5");
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      try {
        Hdf5Writer writer(path, kBlock);
        writer.begin(test_channels(), test_metadata());
        for (std::size_t i = 0; i < kAppended; ++i) writer.append(row_time(i), row_values(i));
        if (explicit_flush) writer.flush();
        std::_Exit(0);
      } catch (...) {
        std::_Exit(1);
      }
    }
    int status = 0;
    REQUIRE(waitpid(child, &status, 0) == child);
    REQUIRE(WIFEXITED(status));
    REQUIRE(WEXITSTATUS(status) == 0);
    const ChannelTable table = fowtsim::io::read_hdf5_channels(path);
    const std::size_t expected = explicit_flush ? kAppended : 2 * kBlock;
    REQUIRE(table.rows() == expected);
    REQUIRE(table.columns[1][expected - 1] == row_values(expected - 1)[0]);
    const Handle file{H5Fopen(path.string().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
    REQUIRE(string_attribute(file.get(), "status") == "running");
  }
}

TEST_CASE("HDF5 writer rejects misuse with errors naming the problem", "[unit]") {
  // Intent: API misuse throws fowtsim::Error (module "io.hdf5"), never corrupts the file.
  const auto dir = fowtsim::testing::scratch_dir("hdf5_misuse");
  {
    Hdf5Writer writer(dir / "a.h5", 16);
    REQUIRE_THROWS_AS(writer.append(0.0, std::vector<double>{1.0, 2.0, 3.0}), fowtsim::Error);
    writer.begin(test_channels(), test_metadata());
    REQUIRE_THROWS_WITH(writer.append(0.0, std::vector<double>{1.0, 2.0}),
                        Catch::Contains("2 values for 3 declared channels"));
    REQUIRE_THROWS_AS(writer.begin(test_channels(), test_metadata()), fowtsim::Error);
    writer.finish(RunEnd{0.0, "completed", 0.0});
    REQUIRE_THROWS_AS(writer.append(0.0, std::vector<double>{1.0, 2.0, 3.0}), fowtsim::Error);
    REQUIRE_THROWS_AS(writer.finish(RunEnd{0.0, "completed", 0.0}), fowtsim::Error);
  }
  auto duplicate = test_channels();
  duplicate.push_back(duplicate.front());
  REQUIRE_THROWS_WITH(Hdf5Writer(dir / "b.h5").begin(duplicate, test_metadata()),
                      Catch::Contains("declared twice"));
  auto reserved = test_metadata();
  reserved.extra.emplace_back("status", "mine");
  REQUIRE_THROWS_WITH(Hdf5Writer(dir / "c.h5").begin(test_channels(), reserved),
                      Catch::Contains("reserved"));
}

TEST_CASE("HDF5 failures are reported with module io.hdf5 and the path", "[unit]") {
  // Intent: an unwritable path gives a fowtsim::Error that says where, not an HDF5 stack dump.
  const auto path = fowtsim::testing::scratch_dir("hdf5_failure") / "missing-dir" / "run.h5";
  Hdf5Writer writer(path);
  try {
    writer.begin(test_channels(), test_metadata());
    FAIL("begin() should have thrown");
  } catch (const fowtsim::Error& error) {
    CHECK(error.context().module == "io.hdf5");
    CHECK_THAT(error.what(), Catch::Contains(path.string()));
  }
  REQUIRE_THROWS_AS(fowtsim::io::read_hdf5_channels(path), fowtsim::InputError);
}

TEST_CASE("Text output reads back within its printed precision, deterministically", "[unit]") {
  // Intent: the OpenFAST-style .out we write is read by the OpenFAST text reader with the same
  // names and units, values within the rounding of 10 significant digits, and no date in the
  // header (two identical runs give identical bytes).
  const auto dir = fowtsim::testing::scratch_dir("text_round_trip");
  constexpr std::size_t kRows = 700;
  TextOutOptions options;
  options.rows_per_flush = 100;
  options.description = "round-trip test";
  for (const char* name : {"a.out", "b.out"}) {
    TextOutWriter writer(dir / name, options);
    writer.begin(test_channels(), test_metadata());
    for (std::size_t i = 0; i < kRows; ++i) writer.append(row_time(i), row_values(i));
    writer.finish(RunEnd{1.0, "completed", row_time(kRows - 1)});
  }
  REQUIRE(read_text_file(dir / "a.out") == read_text_file(dir / "b.out"));

  const ChannelTable table = fowtsim::io::read_openfast_text(dir / "a.out");
  REQUIRE(table.names == std::vector<std::string>{"Time", "PtfmSurge", "RotSpeed", "RootMyc1"});
  REQUIRE(table.units == std::vector<std::string>{"s", "m", "rpm", "kN-m"});
  REQUIRE(table.rows() == kRows);
  CHECK_THAT(table.description, Catch::Contains("round-trip test"));
  // 10 significant digits in d.dddddddddE±XX: rounding to nearest is off by at most half a unit
  // in the 10th digit, i.e. 5e-10 of the value (the mantissa is ≥ 1); 6e-10 leaves room for the
  // binary conversions on both sides.
  constexpr double kRelative = 6e-10;
  for (std::size_t i = 0; i < kRows; ++i) {
    REQUIRE(std::abs(table.time()[i] - row_time(i)) <= kRelative * std::abs(row_time(i)));
    const auto expected = row_values(i);
    for (std::size_t c = 0; c < expected.size(); ++c) {
      REQUIRE(std::abs(table.columns[c + 1][i] - expected[c]) <= kRelative * std::abs(expected[c]));
    }
  }
}

TEST_CASE("Text output takes its number of digits as an option", "[unit]") {
  // Intent: the format is configurable; 4 digits round to within 5e-4 relative; nonsense throws.
  const auto path = fowtsim::testing::scratch_dir("text_digits") / "short.out";
  TextOutOptions options;
  options.significant_digits = 4;
  {
    TextOutWriter writer(path, options);
    writer.begin(test_channels(), test_metadata());
    writer.append(1.0, row_values(3));
    writer.finish(RunEnd{0.0, "completed", 1.0});
  }
  const std::string text = read_text_file(path);
  CHECK_THAT(text, Catch::Contains("1.000E+00\t"));
  const ChannelTable table = fowtsim::io::read_openfast_text(path);
  const auto expected = row_values(3);
  for (std::size_t c = 0; c < expected.size(); ++c) {
    CHECK(std::abs(table.columns[c + 1][0] - expected[c]) <= 5e-4 * std::abs(expected[c]));
  }
  options.significant_digits = 0;
  REQUIRE_THROWS_AS(TextOutWriter(path, options), fowtsim::InputError);
}

TEST_CASE("Flush policy: full blocks, and the clock only every 64 appends", "[unit]") {
  // Intent: a writer flushes on a full block, and on elapsed time only at the 64th append since the
  // last check (here with a zero interval, so every check is due).
  fowtsim::io::FlushPolicy by_rows(10, std::chrono::hours(1));
  for (std::size_t rows = 1; rows < 10; ++rows) REQUIRE_FALSE(by_rows.due(rows));
  REQUIRE(by_rows.due(10));

  fowtsim::io::FlushPolicy by_time(100000, std::chrono::seconds(0));
  for (std::size_t i = 1; i < fowtsim::io::FlushPolicy::kClockCheckEvery; ++i) REQUIRE_FALSE(by_time.due(i));
  REQUIRE(by_time.due(fowtsim::io::FlushPolicy::kClockCheckEvery));
}
