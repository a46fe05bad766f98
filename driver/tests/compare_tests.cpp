// compare_tables: alignment, metrics and pass/fail on small hand-made tables.
#include <cmath>

#include <catch2/catch.hpp>

#include "compare/channel_compare.hpp"
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
  const ComparisonReport r = compare_tables(sine_table(0.1), sine_table(0.1, 1.01), {{1e-3, 1e-9}, {}, {}});
  CHECK_FALSE(r.pass());
  CHECK(r.channels[0].pass);
  CHECK_FALSE(r.channels[1].pass);
  CHECK(r.channels[1].rms_error_over_rms == Approx(0.01).epsilon(1e-9));  // error is exactly 1 % of B
  CHECK(r.channels[1].max_abs_error == Approx(0.03).epsilon(1e-6));       // 1 % of max B = 3
}

TEST_CASE("a test on a finer time grid is interpolated onto the reference samples", "[unit][compare]") {
  // Linear interpolation of sin on a 0.01 s grid errs by at most h²/8 = 1.25e-5.
  const ComparisonReport r = compare_tables(sine_table(0.1), sine_table(0.01), {{0.0, 2e-5}, {}, {}});
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
  CHECK_FALSE(compare_tables(sine_table(0.1), test, {{1.0, 1.0}, {}, {}}).channels[0].pass);
}

TEST_CASE("tables with no common time window are an error", "[unit][compare]") {
  auto late = sine_table(0.1);
  for (double& t : late.columns[0]) t += 100.0;
  CHECK_THROWS_AS(compare_tables(sine_table(0.1), late, {}), InputError);
}
