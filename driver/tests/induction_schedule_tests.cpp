// aero.induction (rigid and Rayleigh–Ritz blades): BEM inductions solved at every RK4 stage
// (`stage`, the default) or at each large step's start and held over its stages (`step`).
#include <algorithm>
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "fowtsim/io/readers.hpp"
#include "fowtsim/testing/skip.hpp"
#include "run/run_scene.hpp"
#include "run_request.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

TEST_CASE("inductions held over a large step's RK4 stages stay within a hair of solving them at every stage", "[verification][aero]") {
  // OC3 in steady 15 m/s (rigid blades, controller), 30 s at ΔT 12.5 ms. Measured: the largest
  // difference of RotSpeed, PtfmPitch, TwrBsMyt and GenPwr is 1.4e-4 of the channel's range (the
  // held induction lags the state by less than a step): 1e-3. And the choice takes effect (> 1e-8).
  const auto dir = testing::scratch_dir("induction_schedule");
  io::ChannelTable runs[2];
  const char* schedule[] = {"stage", "step"};
  for (int k = 0; k < 2; ++k) {
    RunRequest r = run_request(testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml", dir / schedule[k]);
    r.t_max_s = 30.0;
    r.deck_settings = {std::string("aero.induction=") + schedule[k]};
    run_scene(r, nullptr);
    runs[k] = io::read_channels(dir / (std::string(schedule[k]) + ".out"));
  }
  for (const char* name : {"RotSpeed", "PtfmPitch", "TwrBsMyt", "GenPwr"}) {
    const auto column = [&](const io::ChannelTable& t) {
      return t.columns[static_cast<std::size_t>(std::find(t.names.begin(), t.names.end(), name) - t.names.begin())];
    };
    const std::vector<double>& a = column(runs[0]);
    const std::vector<double>& b = column(runs[1]);
    REQUIRE(a.size() == b.size());
    double diff = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) diff = std::max(diff, std::abs(a[i] - b[i]));
    const double range = *std::max_element(a.begin(), a.end()) - *std::min_element(a.begin(), a.end());
    INFO(name << ": largest difference " << diff / range << " of the range");
    CHECK(diff < 1e-3 * range);
    CHECK(diff > 1e-8 * range);
  }
}
