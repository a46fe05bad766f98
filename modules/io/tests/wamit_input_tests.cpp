// WAMIT .1/.3/.hst files: the OpenFAST OC3-Hywind spar's (../shared/reference) read and made
// dimensional as HydroDyn does (WAMITULEN 1, ρ 1025, g 9.80665), and malformed files refused.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <numbers>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/wamit_input.hpp"
#include "fowtsim/testing/skip.hpp"

using namespace fowtsim;
using namespace fowtsim::io;

namespace {

std::filesystem::path spar(const char* extension) {
  return testing::shared_dir_or_skip() / "reference/r-test/glue-codes/openfast/5MW_Baseline/HydroData" /
         (std::string("Spar") + extension);
}

const WamitScales kOc3{1025.0, 9.80665, 1.0};

}  // namespace

TEST_CASE("the OC3 spar's WAMIT radiation file reads into dimensional A(ω), B(ω) and the limits", "[verification][io]") {
  const WamitRadiation r = read_wamit_radiation(spar(".1"), kOc3);
  // Spar.1: PER = −1 (infinite period) Ā11 = 7.787967E+03, Ā15 = −4.745684E+05; PER = 0 (zero
  // period) Ā11 = 7.569865E+03 (×ρ, L = 1).
  REQUIRE(r.added_mass_infinite_frequency);
  REQUIRE(r.added_mass_zero_frequency);
  CHECK((*r.added_mass_zero_frequency)(0, 0) == 7.787967e3 * 1025.0);
  CHECK((*r.added_mass_zero_frequency)(0, 4) == -4.745684e5 * 1025.0);
  CHECK((*r.added_mass_infinite_frequency)(0, 0) == 7.569865e3 * 1025.0);
  CHECK(r.frequencies_rad_s.size() == r.added_mass.size());
  CHECK(r.frequencies_rad_s.size() >= 50);
  for (std::size_t k = 1; k < r.frequencies_rad_s.size(); ++k) CHECK(r.frequencies_rad_s[k] > r.frequencies_rad_s[k - 1]);
  // Radiation damping is dissipative: B11, B33, B55 ≥ 0 at every frequency (WAMIT's panels to 1e-6).
  for (const Mat6& b : r.damping)
    for (int i : {0, 2, 4}) CHECK(b(i, i) >= -1e-6 * b.cwiseAbs().maxCoeff());
  // A spar of 9.4 m diameter: the surge added mass at infinite frequency is about ρ × its
  // submerged volume (8,029 m³, Ca = 1 strip theory: 8.23e6 kg); WAMIT's 3-D flow gives less at the
  // ends (measured 5.7 % less): within 10 %.
  CHECK(std::abs((*r.added_mass_infinite_frequency)(0, 0) / (1025.0 * 8029.21) - 1.0) < 0.10);
}

TEST_CASE("the OC3 spar's WAMIT excitation and hydrostatics read dimensionally", "[verification][io]") {
  const WamitExcitation x = read_wamit_excitation(spar(".3"), kOc3);
  REQUIRE_FALSE(x.headings_deg.empty());
  CHECK(x.headings_deg.front() == -180.0);
  REQUIRE(x.force.size() == x.headings_deg.size());
  // Spar.3, first line: PER 125.664 s, β −180°, mode 1: Re −7.335110E-05, Im −1.411370E+01 (×ρ g).
  const std::size_t first = 0;  // the longest period is the lowest frequency
  CHECK(x.frequencies_rad_s[first] == Approx(2.0 * std::numbers::pi / 125.664).epsilon(1e-12));
  CHECK(x.force[0][first][0].imag() == Approx(-1.411370e1 * 1025.0 * 9.80665).epsilon(1e-12));
  const Mat6 c = read_wamit_hydrostatics(spar(".hst"), kOc3);
  // C̄33 = 33.12247: ρ g × the waterplane area (π 3.25² = 33.18 m² for the 6.5 m column, WAMIT's
  // panels 0.2 % less); C̄44 = C̄55 = −4.973414E+05 (×ρ g; negative: the spar's buoyancy about the
  // WAMIT origin at the waterline, the weight's share is added by the structure).
  CHECK(c(2, 2) == Approx(33.12247 * 1025.0 * 9.80665).epsilon(1e-12));
  CHECK(std::abs(c(2, 2) / (1025.0 * 9.80665 * std::numbers::pi * 3.25 * 3.25) - 1.0) < 0.005);
  CHECK(c(3, 3) == Approx(-4.973414e5 * 1025.0 * 9.80665).epsilon(1e-12));
  CHECK(c(0, 0) == 0.0);
}

TEST_CASE("a malformed WAMIT line is refused with its file and line", "[unit][io]") {
  const auto dir = testing::scratch_dir("wamit_bad");
  std::ofstream(dir / "bad.1") << "  -1  1  1  7.78E+03\n  10.0  1  7  1.0  2.0\n";
  CHECK_THROWS_WITH(read_wamit_radiation(dir / "bad.1", kOc3), Catch::Contains("bad.1:2") && Catch::Contains("mode 7"));
  std::ofstream(dir / "bad.hst") << "1 1 abc\n";
  CHECK_THROWS_WITH(read_wamit_hydrostatics(dir / "bad.hst", kOc3), Catch::Contains("bad.hst:1") && Catch::Contains("abc"));
  std::ofstream(dir / "short.1") << "10.0 1 1 1.0\n";
  CHECK_THROWS_WITH(read_wamit_radiation(dir / "short.1", kOc3), Catch::Contains("short.1:1") && Catch::Contains("5 fields"));
}

namespace {

// A small complete .1 file: the two limits and two periods, each with the pairs (1, 1), (3, 3), (1, 5).
const char* kSmallRadiation =
    "-1 1 1 1.0\n-1 3 3 2.0\n-1 1 5 3.0\n"
    " 0 1 1 1.1\n 0 3 3 2.1\n 0 1 5 3.1\n"
    "10 1 1 1.2 0.1\n10 3 3 2.2 0.2\n10 1 5 3.2 0.3\n"
    " 5 1 1 1.3 0.4\n 5 3 3 2.3 0.5\n 5 1 5 3.3 0.6\n";

// A .3 file of two periods × two headings, modes 1 and 3.
const char* kSmallExcitation =
    "10 0 1 1 0 1 0\n10 0 3 1 0 1 0\n10 90 1 1 0 1 0\n10 90 3 1 0 1 0\n"
    " 5 0 1 1 0 1 0\n 5 0 3 1 0 1 0\n 5 90 1 1 0 1 0\n 5 90 3 1 0 1 0\n";

std::filesystem::path write(const std::filesystem::path& dir, const char* name, const std::string& text) {
  std::ofstream(dir / name, std::ios::binary) << text;
  return dir / name;
}

}  // namespace

TEST_CASE("a WAMIT file cut inside its last number is refused: its last line has no line end", "[unit][io]") {
  // "3.3 0.6" cut to "3.3 0." reads as numbers; only the missing line end tells.
  const auto dir = testing::scratch_dir("wamit_cut_number");
  const std::string whole = kSmallRadiation;
  REQUIRE_NOTHROW(read_wamit_radiation(write(dir, "whole.1", whole), kOc3));
  CHECK_THROWS_WITH(read_wamit_radiation(write(dir, "cut.1", whole.substr(0, whole.size() - 2)), kOc3),
                    Catch::Contains("cut.1:12") && Catch::Contains("without a line end"));
  const std::string x = kSmallExcitation;
  CHECK_THROWS_WITH(read_wamit_excitation(write(dir, "cut.3", x.substr(0, x.size() - 1)), kOc3),
                    Catch::Contains("cut.3:8") && Catch::Contains("without a line end"));
  // Trailing blank lines after a complete last line, and CRLF line ends, are no truncation.
  REQUIRE_NOTHROW(read_wamit_radiation(write(dir, "blank_tail.1", whole + "\n  "), kOc3));
  std::string crlf;
  for (char c : whole) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  REQUIRE_NOTHROW(read_wamit_radiation(write(dir, "crlf.1", crlf), kOc3));
}

TEST_CASE("a WAMIT .1 period missing pairs the others have is refused with the pairs and its line", "[unit][io]") {
  const auto dir = testing::scratch_dir("wamit_cut_block");
  // Cut at a line end inside the last period: (1, 5) of period 5 s is missing.
  const std::string whole = kSmallRadiation;
  const std::string cut = whole.substr(0, whole.rfind(" 5 1 5"));
  CHECK_THROWS_WITH(read_wamit_radiation(write(dir, "cut.1", cut), kOc3),
                    Catch::Contains("cut.1:11") && Catch::Contains("period 5 s holds 2 entries") && Catch::Contains("missing (1, 5)"));
  // The same (period, i, j) twice is refused, naming the first.
  CHECK_THROWS_WITH(read_wamit_radiation(write(dir, "twice.1", whole + "5 1 1 9.9 0.1\n"), kOc3),
                    Catch::Contains("twice.1:13") && Catch::Contains("(1, 1) of period 5 s again (first on line 10)"));
}

TEST_CASE("a WAMIT .3 period and heading missing modes, or a .hst without all 36 entries, is refused", "[unit][io]") {
  const auto dir = testing::scratch_dir("wamit_cut_excitation");
  const std::string x = kSmallExcitation;
  const std::string cut = x.substr(0, x.rfind(" 5 90 3"));
  CHECK_THROWS_WITH(read_wamit_excitation(write(dir, "cut.3", cut), kOc3),
                    Catch::Contains("cut.3:7") && Catch::Contains("heading 90° holds 1 entries") && Catch::Contains("missing mode 3"));
  std::string hst;
  for (int i = 1; i <= 6; ++i)
    for (int j = 1; j <= 6; ++j) hst += fmt::format("{} {} {}\n", i, j, i == j ? 1.0 : 0.0);
  REQUIRE_NOTHROW(read_wamit_hydrostatics(write(dir, "whole.hst", hst), kOc3));
  CHECK_THROWS_WITH(read_wamit_hydrostatics(write(dir, "cut.hst", hst.substr(0, hst.find("6 1 "))), kOc3),
                    Catch::Contains("cut.hst:30") && Catch::Contains("30 of the 36 entries"));
}

TEST_CASE("WAMIT .1 and .3 files cut at a period boundary are complete alone; their periods differ", "[unit][io]") {
  const auto dir = testing::scratch_dir("wamit_periods");
  const std::string x = kSmallExcitation;
  const WamitRadiation r = read_wamit_radiation(write(dir, "run.1", kSmallRadiation), kOc3);
  const WamitExcitation whole = read_wamit_excitation(write(dir, "run.3", x), kOc3);
  REQUIRE_NOTHROW(check_same_frequencies(r, dir / "run.1", whole, dir / "run.3"));
  // The .3 file without its second period (all its headings): complete in itself.
  const WamitExcitation cut = read_wamit_excitation(write(dir, "cut.3", x.substr(0, x.find(" 5 0 1"))), kOc3);
  CHECK_THROWS_WITH(check_same_frequencies(r, dir / "run.1", cut, dir / "cut.3"),
                    Catch::Contains("run.1") && Catch::Contains("cut.3") && Catch::Contains("run.1: 2 from") &&
                        Catch::Contains("cut.3: 1 from"));
}

TEST_CASE("a directory where a WAMIT file belongs is named as a directory", "[unit][io]") {
  const auto dir = testing::scratch_dir("wamit_directory");
  std::filesystem::create_directories(dir / "Spar.1");
  CHECK_THROWS_WITH(read_wamit_radiation(dir / "Spar.1", kOc3), Catch::Contains("Spar.1' is a directory"));
}
