// Tests of the OpenFAST binary (.outb) writer: read back bit-exactly by read_openfast_binary, the
// header kept current while the run goes (a killed run's file reads), whole rows only on a failed
// write, evenly spaced rows only.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include <csignal>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/outb_writer.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/testing/skip.hpp"

namespace {

using fowtsim::ChannelInfo;
using fowtsim::io::ChannelTable;
using fowtsim::io::OutbWriter;
using fowtsim::io::RunMetadata;

std::vector<ChannelInfo> channels() {
  return {{"PtfmSurge", "m", "platform surge", "test"},
          {"RotSpeed", "rpm", "rotor speed", "test"},
          {"RootMyc1", "kN-m", "flapwise root moment", "test"},
          {"Awkward", "-", "values with every kind of bit pattern", "test"}};
}

RunMetadata metadata() {
  RunMetadata m;
  m.version = "0.1.0";
  m.deck_path = "/decks/test.yaml";
  m.deck_hash = "0123456789abcdef";
  return m;
}

// Irrational fractions, signs, subnormals, a negative zero and huge exponents: "bit-exact" bites.
std::vector<double> row_values(std::size_t row) {
  const double x = static_cast<double>(row);
  const double awkward[] = {-0.0, std::numeric_limits<double>::denorm_min() * (x + 1.0), 1.0e300 / (x + 1.0), -1.0 / 3.0};
  return {std::sin(0.1 * x) * 1.0e-3, 12.1 + std::cos(0.37 * x) / 3.0, -std::exp(0.01 * x) * 1.0e5, awkward[row % 4]};
}
double row_time(std::size_t row) { return 0.0125 * static_cast<double>(row); }

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void write_rows(OutbWriter& writer, std::size_t from, std::size_t to) {
  for (std::size_t i = from; i < to; ++i) writer.append(row_time(i), row_values(i));
}

void check_rows(const ChannelTable& table, std::size_t rows) {
  REQUIRE(table.rows() == rows);
  for (std::size_t i = 0; i < rows; ++i) {
    CHECK(table.time()[i] == Approx(row_time(i)).margin(1e-12));
    const std::vector<double> expected = row_values(i);
    for (std::size_t c = 0; c < expected.size(); ++c)
      if (!same_bits(table.columns[c + 1][i], expected[c])) FAIL("row " << i << " channel " << c << " differs");
  }
}

std::int32_t header_row_count(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(6);
  std::int32_t nt = -1;
  in.read(reinterpret_cast<char*>(&nt), sizeof nt);
  return nt;
}

void set_header_row_count(const std::filesystem::path& path, std::int32_t nt) {
  std::fstream io(path, std::ios::binary | std::ios::in | std::ios::out);
  io.seekp(6);
  io.write(reinterpret_cast<const char*>(&nt), sizeof nt);
}

}  // namespace

TEST_CASE("An .outb reads back bit-exactly, with its names, units, status and deck", "[unit]") {
  const auto dir = fowtsim::testing::scratch_dir("outb_round_trip");
  const auto path = dir / "run.outb";
  constexpr std::size_t kRows = 2 * 64 + 17;  // several flushes and a partial block
  {
    OutbWriter writer(path, 64);
    writer.begin(channels(), metadata());
    write_rows(writer, 0, kRows);
    writer.finish({1.5, "completed", row_time(kRows - 1), {}});
  }
  const ChannelTable table = fowtsim::io::read_openfast_binary(path);
  check_rows(table, kRows);
  CHECK(table.names == std::vector<std::string>{"Time", "PtfmSurge", "RotSpeed", "RootMyc1", "Awkward"});
  CHECK(table.units == std::vector<std::string>{"s", "m", "rpm", "kN-m", "-"});
  CHECK(table.status == "completed");
  CHECK(table.description.find("0123456789abcdef") != std::string::npos);  // restarts look for the deck hash
  CHECK(table.warnings.empty());
  CHECK(header_row_count(path) == static_cast<std::int32_t>(kRows));
  std::ifstream in(path, std::ios::binary);
  std::int16_t file_id = 0;
  in.read(reinterpret_cast<char*>(&file_id), sizeof file_id);
  CHECK(file_id == 3);
}

TEST_CASE("A killed run's .outb reads to its last flush; rows past its header's count read with a warning", "[unit]") {
  // A child appends 2.5 blocks and ends with _Exit inside the writer's scope, as if killed: no
  // destructor, no finish. The header counts every block written.
  const auto dir = fowtsim::testing::scratch_dir("outb_killed");
  const auto path = dir / "killed.outb";
  constexpr std::size_t kBlock = 32;
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    try {
      OutbWriter writer(path, kBlock);
      writer.begin(channels(), metadata());
      write_rows(writer, 0, 2 * kBlock + kBlock / 2);
      std::_Exit(0);
    } catch (...) {
      std::_Exit(1);
    }
  }
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  REQUIRE((WIFEXITED(status) && WEXITSTATUS(status) == 0));
  ChannelTable table = fowtsim::io::read_openfast_binary(path);
  check_rows(table, 2 * kBlock);
  CHECK(table.status == "running");
  CHECK(table.warnings.empty());

  // Killed between writing a block and counting it: the header says fewer rows than the file holds.
  set_header_row_count(path, static_cast<std::int32_t>(kBlock));
  table = fowtsim::io::read_openfast_binary(path);
  check_rows(table, 2 * kBlock);
  REQUIRE(table.warnings.size() == 1);
  CHECK_THAT(table.warnings[0], Catch::Contains("header says 32 rows but the file holds 64 whole rows"));

  // And killed inside a write: a row cut short is dropped.
  { std::ofstream(path, std::ios::binary | std::ios::app).write("\1\2\3", 3); }
  table = fowtsim::io::read_openfast_binary(path);
  check_rows(table, 2 * kBlock);
  CHECK_THAT(table.warnings.at(0), Catch::Contains("and part of one"));
}

TEST_CASE("A failed .outb write leaves whole rows only, and the rows are written once there is room", "[unit]") {
  // A file-size limit stands in for a full disk (write fails with EFBIG after a partial write).
  const auto dir = fowtsim::testing::scratch_dir("outb_full");
  const auto path = dir / "full.outb";
  constexpr std::size_t kRows = 40;
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    try {
      OutbWriter writer(path, 1000);
      writer.begin(channels(), metadata());
      const auto header = std::filesystem::file_size(path);
      // Room for 10.5 rows: the flush of 20 fails part-way.
      rlimit limit{static_cast<rlim_t>(header + 10 * 32 + 16), RLIM_INFINITY};
      if (setrlimit(RLIMIT_FSIZE, &limit) != 0) std::_Exit(3);
      write_rows(writer, 0, 20);
      bool failed = false;
      try {
        writer.flush();
      } catch (const fowtsim::Error&) {
        failed = true;
      }
      if (!failed) std::_Exit(4);
      if (std::filesystem::file_size(path) != header) std::_Exit(5);  // cut back: no part of a row
      limit.rlim_cur = RLIM_INFINITY;
      if (setrlimit(RLIMIT_FSIZE, &limit) != 0) std::_Exit(3);
      write_rows(writer, 20, kRows);
      writer.finish({0.1, "completed", row_time(kRows - 1), {}});
      std::_Exit(0);
    } catch (...) {
      std::_Exit(1);
    }
  }
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  const ChannelTable table = fowtsim::io::read_openfast_binary(path);
  check_rows(table, kRows);
  CHECK(table.status == "completed");
}

TEST_CASE("The .outb writer refuses rows off the even time grid, and says which names it cuts", "[unit]") {
  const auto dir = fowtsim::testing::scratch_dir("outb_misuse");
  OutbWriter writer(dir / "uneven.outb");
  writer.begin(channels(), metadata());
  write_rows(writer, 0, 3);
  CHECK_THROWS_WITH(writer.append(row_time(3) + 1e-4, row_values(3)), Catch::Contains("evenly spaced"));
  writer.append(row_time(3) + 1e-12, row_values(3));  // rounding of t0 + k dt is no reason to refuse
  CHECK_THROWS_WITH(writer.append(0.1, std::vector<double>{1.0}), Catch::Contains("1 values for 4 declared channels"));

  CHECK(fowtsim::io::outb_name_note(channels()).empty());
  const std::string note = fowtsim::io::outb_name_note({{"BldPitchAct1", "deg", "", ""},
                                                        {"BldPitchAct2", "deg", "", ""},
                                                        {"HydroMorFxi", "N", "", ""},
                                                        {"RotSpeed", "rpm", "", ""}});
  CHECK_THAT(note, Catch::Contains("3 names cut") && Catch::Contains("HydroMorFxi → HydroMorFx") &&
                       Catch::Contains("BldPitchAc (2 columns"));
}
