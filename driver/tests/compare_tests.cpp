// compare_tables: alignment, metrics, statistics, units, aliases and pass/fail on small hand-made
// tables, and the table `fowtsim compare` prints.
#include <cmath>
#include <cstdio>

#include <catch2/catch.hpp>

#include <fmt/format.h>

#include "compare/channel_compare.hpp"
#include "compare/comparison_table.hpp"
#include "fowtsim/core/error.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

io::ChannelTable sine_table(double dt, double scale_b = 1.0) {
  io::ChannelTable t;
  t.names = {"Time", "A", "B"};
  t.units = {"s", "m", "N"};
  t.columns.resize(3);
  for (double time = 0; time <= 10.0 + 1e-12; time += dt) {
    t.columns[0].push_back(time);
    t.columns[1].push_back(std::sin(time));
    t.columns[2].push_back(scale_b * (2.0 + std::cos(time)));
  }
  return t;
}

CompareOptions with_tolerance(ChannelTolerance tolerance) {
  CompareOptions options;
  options.default_tolerance = tolerance;
  return options;
}

}  // namespace

TEST_CASE("identical tables pass with zero error and unit correlation", "[unit][compare]") {
  const auto t = sine_table(0.1);
  const ComparisonReport r = compare_tables(t, t, {});
  REQUIRE(r.channels.size() == 2);
  CHECK(r.pass());
  CHECK(r.channels[0].max_abs_error == 0.0);
  CHECK(r.channels[0].correlation == Approx(1.0));
}

TEST_CASE("one channel off by 1 % fails alone, with the metrics of a 1 % error", "[unit][compare]") {
  const ComparisonReport r = compare_tables(sine_table(0.1), sine_table(0.1, 1.01), with_tolerance({1e-3, 1e-9, 0.0}));
  CHECK_FALSE(r.pass());
  CHECK(r.channels[0].pass);
  CHECK_FALSE(r.channels[1].pass);
  CHECK(r.channels[1].rms_error_over_rms == Approx(0.01).epsilon(1e-9));  // error is exactly 1 % of B
  CHECK(r.channels[1].max_abs_error == Approx(0.03).epsilon(1e-6));       // 1 % of max B = 3
}

TEST_CASE("a test on a finer time grid is interpolated onto the reference samples", "[unit][compare]") {
  // Linear interpolation of sin on a 0.01 s grid errs by at most h²/8 = 1.25e-5.
  const ComparisonReport r = compare_tables(sine_table(0.1), sine_table(0.01), with_tolerance({0.0, 2e-5, 0.0}));
  CHECK(r.pass());
  CHECK(r.channels[0].max_abs_error < 1.25e-5);
  CHECK(r.samples == 101);
}

TEST_CASE("requested channels that are missing fail; unrequested extras are only reported", "[unit][compare]") {
  auto ref = sine_table(0.1), test = sine_table(0.1);
  test.names[2].assign(std::string("C"));  // (assign from string: GCC 12 -Wrestrict false positive on = "C")
  const ComparisonReport all = compare_tables(ref, test, {});
  CHECK(all.pass());  // B missing in test is reported, not required
  CHECK(all.missing_in_test == std::vector<std::string>{"B"});
  CHECK(all.missing_in_reference == std::vector<std::string>{"C"});
  CompareOptions asked;
  asked.channels = {"A", "B"};
  CHECK_FALSE(compare_tables(ref, test, asked).pass());
}

TEST_CASE("a NaN in the test fails the channel", "[unit][compare]") {
  auto test = sine_table(0.1);
  test.columns[1][5] = NAN;
  CHECK_FALSE(compare_tables(sine_table(0.1), test, with_tolerance({1.0, 1.0, 0.0})).channels[0].pass);
}

TEST_CASE("tables with no common time window are an error", "[unit][compare]") {
  auto late = sine_table(0.1);
  for (double& t : late.columns[0]) t += 100.0;
  CHECK_THROWS_AS(compare_tables(sine_table(0.1), late, {}), InputError);
}

TEST_CASE("the default tolerance scales its absolute part with each channel's range", "[unit][compare]") {
  // A 0.05 % offset of the range passes the code-to-code default (1e-3·|ref| + 1e-3·range) even at
  // the zero crossings of A, where a purely relative bound fails; a 1 % error fails it.
  auto shifted = sine_table(0.1);
  for (double& a : shifted.columns[1]) a += 0.0005 * 2.0;
  CHECK(compare_tables(sine_table(0.1), shifted, {}).pass());
  CompareOptions relative_only;
  relative_only.default_tolerance = {1e-3, 0.0, 0.0};
  CHECK_FALSE(compare_tables(sine_table(0.1), shifted, relative_only).pass());
  CHECK_FALSE(compare_tables(sine_table(0.1), sine_table(0.1, 1.01), {}).pass());
}

TEST_CASE("compare over a window, by statistics, through aliases", "[unit][compare]") {
  auto test = sine_table(0.1);
  for (std::size_t i = 0; i < test.rows(); ++i)
    if (test.time()[i] < 2.0) test.columns[2][i] += 100.0;  // a start-up transient
  CompareOptions windowed;
  windowed.window = std::pair(2.0, 10.0);
  const ComparisonReport w = compare_tables(sine_table(0.1), test, windowed);
  CHECK(w.pass());
  CHECK(w.t_start_s == 2.0);
  CHECK_FALSE(compare_tables(sine_table(0.1), test, {}).pass());
  // Statistics: B scaled by 1.01 moves mean and std by 1 %: passes 2 %, fails 0.5 %.
  CompareOptions stats;
  stats.statistics = true;
  stats.statistics_percent = 2.0;
  const ComparisonReport s = compare_tables(sine_table(0.1), sine_table(0.1, 1.01), stats);
  CHECK(s.pass());
  CHECK(s.channels[1].test_statistics[kMean] == Approx(1.01 * s.channels[1].reference_statistics[kMean]));
  stats.statistics_percent = 0.5;
  CHECK_FALSE(compare_tables(sine_table(0.1), sine_table(0.1, 1.01), stats).pass());
  // Aliases: the test calls B "Bee".
  auto renamed = sine_table(0.1);
  renamed.names[2] = "Bee";
  CompareOptions aliased;
  aliased.aliases["B"] = "Bee";
  const ComparisonReport a = compare_tables(sine_table(0.1), renamed, aliased);
  CHECK(a.channels.size() == 2);
  CHECK(a.pass());
}

TEST_CASE("a required channel missing is reported once, and --channels reports only those", "[unit][compare]") {
  auto test = sine_table(0.1);
  test.names.push_back("Extra");
  test.units.push_back("-");
  test.columns.push_back(test.columns[1]);
  CompareOptions options;
  options.channels = {"A", "Nowhere"};
  const ComparisonReport r = compare_tables(sine_table(0.1), test, options);
  REQUIRE(r.required_missing.size() == 1);
  CHECK(r.required_missing[0].name == "Nowhere");
  CHECK(r.missing_in_test.empty());
  CHECK(r.missing_in_reference.empty());  // "Extra" was not asked for
  CHECK_FALSE(r.pass());
}

TEST_CASE("a constant reference channel has no ratio, and says so", "[unit][compare]") {
  auto t = sine_table(0.1);
  for (double& b : t.columns[2]) b = 3.0;
  const ComparisonReport r = compare_tables(t, t, {});
  CHECK(r.channels[1].constant_reference);
  CHECK(r.pass());
}

TEST_CASE("compare --stats --wohler adds the damage-equivalent load", "[unit][compare]") {
  // 2 + cos t against 2 + cos 2t over ten periods of the first: the same mean, std, min and max
  // (whole periods), twice the cycles of the same range, so the DEL grows by 2^{1/m} exactly.
  const auto table = [](double frequency) {
    io::ChannelTable t;
    t.names = {"Time", "B"};
    t.units = {"s", "N"};
    t.columns.resize(2);
    for (int i = 0; i <= 20000; ++i) {
      const double time = 20.0 * 3.141592653589793 * i / 20000.0;
      t.columns[0].push_back(time);
      t.columns[1].push_back(2.0 + std::cos(frequency * time));
    }
    return t;
  };
  CompareOptions stats;
  stats.statistics = true;
  stats.statistics_percent = 2.0;
  CHECK(compare_tables(table(1.0), table(2.0), stats).pass());  // mean and std alone agree
  stats.wohler_exponent = 4.0;
  const ComparisonReport r = compare_tables(table(1.0), table(2.0), stats);
  const ChannelComparison& b = r.channels.at(0);
  // 10 and 20 cycles of range 2 over 20π s (rounding of the sampled peaks: 1e-9)
  CHECK(b.reference_statistics[kDel] == Approx(2.0 * std::pow(10.0 / (20.0 * 3.141592653589793), 0.25)).epsilon(1e-9));
  CHECK(b.test_statistics[kDel] == Approx(std::pow(2.0, 0.25) * b.reference_statistics[kDel]).epsilon(1e-9));
  CHECK(b.difference_percent[kDel] == Approx(100.0 * (std::pow(2.0, 0.25) - 1.0)).epsilon(1e-9));  // 18.9 %
  CHECK_FALSE(r.pass());
  stats.wohler_exponent.reset();  // no exponent, no DEL
  CHECK(std::isnan(compare_tables(table(1.0), table(2.0), stats).channels.at(0).test_statistics[kDel]));
}

TEST_CASE("compare --stats judges a mean by the channel's spread and a std by itself", "[unit][compare]") {
  CompareOptions stats;
  stats.statistics = true;  // the default 5 %
  // A: sin t over 0–10 s (mean 0.18, std 0.67). Shifted by 0.02: Δmean is 3 % of the std, a pass,
  // where a relative difference of the means would be 11 %.
  auto shifted = sine_table(0.1);
  for (double& a : shifted.columns[1]) a += 0.02;
  const ComparisonReport r = compare_tables(sine_table(0.1), shifted, stats);
  const ChannelComparison& a = r.channels.at(0);
  CHECK(a.difference_percent[kMean] == Approx(100.0 * 0.02 / a.reference_statistics[kStd]).epsilon(1e-9));
  CHECK(std::abs(a.difference_percent[kStd]) < 1e-9);
  CHECK(a.pass);
  // B: 2 + cos t, its spread about its mean scaled by 1.1: Δstd +10 % of the std fails, the mean stays.
  auto wider = sine_table(0.1);
  const double mean_b = compare_tables(sine_table(0.1), sine_table(0.1), stats).channels.at(1).reference_statistics[kMean];
  for (double& b : wider.columns[2]) b = mean_b + 1.1 * (b - mean_b);
  const ComparisonReport w = compare_tables(sine_table(0.1), wider, stats);
  CHECK(w.channels.at(1).difference_percent[kStd] == Approx(10.0).epsilon(1e-9));
  CHECK(std::abs(w.channels.at(1).difference_percent[kMean]) < 1e-9);
  CHECK_FALSE(w.channels.at(1).pass);
  CHECK(w.passed() == 1);
  CHECK_FALSE(w.pass());
}

TEST_CASE("a channel constant at zero passes only against zero", "[unit][compare]") {
  auto zero = sine_table(0.1), small = sine_table(0.1);
  for (double& b : zero.columns[2]) b = 0.0;
  for (double& b : small.columns[2]) b = 1e-3;
  CompareOptions stats;
  stats.statistics = true;
  CHECK(compare_tables(zero, zero, stats).pass());
  const ChannelComparison c = compare_tables(zero, small, stats).channels.at(1);
  CHECK(std::isinf(c.difference_percent[kMean]));  // no scale to judge 1e-3 against
  CHECK_FALSE(c.pass);
}

TEST_CASE("units are converted or refused, never compared as they are", "[unit][compare]") {
  // B written in kN by the reference and in N by the test: the same load.
  auto in_newton = sine_table(0.1, 1000.0);
  auto in_kilonewton = sine_table(0.1);
  in_kilonewton.units[2] = "kN";
  const ComparisonReport r = compare_tables(in_kilonewton, in_newton, {});
  CHECK(r.pass());
  CHECK(r.channels.at(1).unit_factor == 1e-3);
  CHECK(r.channels.at(1).max_abs_error < 1e-12);
  // A moment against a force: not compared, and the comparison fails with why.
  in_newton.units[2] = "N-m";
  const ComparisonReport refused = compare_tables(in_kilonewton, in_newton, {});
  CHECK(refused.channels.size() == 1);
  REQUIRE(refused.refused.size() == 1);
  CHECK(refused.refused[0].name == "B");
  CHECK_THAT(refused.refused[0].reason, Catch::Contains("force") && Catch::Contains("moment"));
  CHECK_FALSE(refused.pass());
}

TEST_CASE("MAP++'s T[1] is compared with our FAIRTEN1 without being told", "[unit][compare]") {
  auto openfast = sine_table(0.1), ours = sine_table(0.1, 1e-3);
  openfast.names[2] = "T[1]";
  openfast.units[2] = "[N]";  // as MAP++ writes it
  ours.names[2] = "FAIRTEN1";
  ours.units[2] = "kN";
  const ComparisonReport r = compare_tables(openfast, ours, {});
  REQUIRE(r.channels.size() == 2);
  CHECK(r.channels[1].name == "T[1]");
  CHECK(r.channels[1].test_name == "FAIRTEN1");
  CHECK(r.channels[1].unit == "N");
  CHECK(r.channels[1].unit_factor == 1e3);
  CHECK(r.missing_in_reference.empty());
  CHECK(r.pass());
}

TEST_CASE("an OpenFAST channel marked INVALID is set aside, not compared", "[unit][compare]") {
  auto openfast = sine_table(0.1);
  openfast.units[2] = "INVALID";  // ElastoDyn's blade loads in a BeamDyn run
  const ComparisonReport r = compare_tables(openfast, sine_table(0.1, 2.0), {});
  CHECK(r.channels.size() == 1);
  CHECK(r.invalid == std::vector<std::string>{"B"});
  CHECK(r.pass());
  CompareOptions asked;
  asked.channels = {"B"};
  const ComparisonReport a = compare_tables(openfast, sine_table(0.1), asked);
  REQUIRE(a.required_missing.size() == 1);
  CHECK_THAT(a.required_missing[0].reason, Catch::Contains("INVALID"));
}

TEST_CASE("channels asked for and absent are each given a reason", "[unit][compare]") {
  auto openfast = sine_table(0.1);
  openfast.names[2] = "T[1]";
  auto ours = sine_table(0.1);
  ours.names[2] = "FAIRTEN1";
  CompareOptions options;
  options.channels = {"TTDspFA", "Aa", "T[1]"};
  const ComparisonReport r = compare_tables(openfast, ours, options);
  REQUIRE(r.required_missing.size() == 2);  // T[1] is found as FAIRTEN1
  CHECK_THAT(r.required_missing[0].reason, Catch::Contains("in neither file") && Catch::Contains("flexible tower"));
  CHECK_THAT(r.required_missing[1].reason, Catch::Contains("did you mean `A`?"));
  CHECK(r.channels.size() == 1);
}

TEST_CASE("the comparison table counts passes and summarises one-file channels in one line", "[unit][compare]") {
  auto ref = sine_table(0.1);
  for (int i = 0; i < 12; ++i) {
    ref.names.push_back(fmt::format("Only{:02}", i));
    ref.units.push_back("m");
    ref.columns.push_back(ref.columns[1]);
  }
  CompareOptions stats;
  stats.statistics = true;
  const ComparisonReport r = compare_tables(ref, sine_table(0.1, 1.2), stats);
  std::FILE* f = std::tmpfile();
  print_comparison(f, r);
  std::rewind(f);
  std::string text;
  for (int c; (c = std::fgetc(f)) != EOF;) text += static_cast<char>(c);
  std::fclose(f);
  CHECK_THAT(text, Catch::Contains("1 of 2 channels within 5 %"));
  CHECK_THAT(text, Catch::Contains("12 channels only in the reference: Only00, Only01") &&
                       Catch::Contains("Only09, … (first 10)") && !Catch::Contains("Only10"));
  CHECK_THAT(text, Catch::Contains("+20.0") && Catch::EndsWith("FAIL\n"));
}
