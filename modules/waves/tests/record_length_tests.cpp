// Irregular and replayed seas repeat with their record's period: a run longer than it meets the
// same waves again, which repeat_warning says; still water and regular waves never warn.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "fowtsim/waves/record_length.hpp"

using namespace fowtsim::waves;

TEST_CASE("an irregular sea shorter than the run is reported as repeating, naming the times", "[unit]") {
  WaveParams p;
  p.model = WaveModel::jonswap;
  p.hs_m = 2.0;
  p.tp_s = 8.0;
  p.duration_s = 30.0;
  CHECK(repeat_period_s(p) == 30.0);
  CHECK_FALSE(repeat_warning(p, 30.0));  // one period: the run ends on the sea it started with
  const auto warning = repeat_warning(p, 60.0);
  REQUIRE(warning);
  CHECK_THAT(*warning, Catch::Contains("repeats every 30 s (waves.duration_s)") &&
                           Catch::Contains("waves at t = 35 s are those at t = 5 s") && Catch::Contains("waves.duration_s ≥ 60"));
  p.model = WaveModel::regular;
  p.height_m = 2.0;
  p.period_s = 8.0;
  CHECK_FALSE(repeat_warning(p, 1e4));
  CHECK_FALSE(repeat_warning(WaveParams{}, 1e4));  // still water
}

TEST_CASE("a replayed elevation record shorter than the run is reported with its source", "[unit]") {
  std::vector<double> t, eta;
  for (int j = 0; j < 40; ++j) {  // 40 samples of 0.5 s: D = 20 s
    t.push_back(0.5 * j);
    eta.push_back(std::sin(0.3 * j));
  }
  const WaveParams p = with_elevation_record(WaveParams{}, t, eta, "wave1elev.txt");
  CHECK(repeat_period_s(p) == Approx(20.0));
  const auto warning = repeat_warning(p, 25.0);
  REQUIRE(warning);
  CHECK_THAT(*warning, Catch::Contains("elevation record wave1elev.txt") && Catch::Contains("as long as the run"));
}
