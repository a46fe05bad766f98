// The module contract (Wave1Elev …) and the seed's load cases.
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/core/module.hpp"
#include "fowtsim/waves/waves_module.hpp"
#include "test_waves.hpp"

using namespace waves_test;

static_assert(fowtsim::Module<Waves>);

TEST_CASE("Waves module writes Wave1Elev at the deck's probes", "[unit][waves]") {
  WaveParams p = jonswap(6.0, 10.0, 3.3, 320.0, 600.0, 0.25, 8);
  p.elevation_probes_m = {{0.0, 0.0}, {25.0, -6.0}};
  const Waves::Params params = Waves::make_params(p);
  const auto channels = Waves::channels(params);
  REQUIRE(channels.size() == 2);
  CHECK(channels[0].name == "Wave1Elev");
  CHECK(channels[0].unit == "m");
  CHECK(channels[1].name == "Wave2Elev");
  CHECK(channels[1].module == "waves");

  Waves::State state = Waves::make_state(params);
  const Waves::Input input;
  double t = 0.0;
  for (int k = 0; k < 50; ++k, t += 0.1) {
    Waves::advance(params, input, t, 0.1, state);
    const Waves::State copy = state;
    const Waves::Output out = Waves::outputs(params, input, state);
    CHECK(out.probe_count == 2);
    // cubic interpolation of the 0.25 s record: within 3e-3 of σ_η = 1.5 m (precomputed tests)
    CHECK(out.elevation_m[0] == Approx(params.field->elevation(0.0, 0.0, t + 0.1)).margin(5e-3));
    CHECK(out.elevation_m[1] == Approx(params.field->elevation(25.0, -6.0, t + 0.1)).margin(5e-3));
    // outputs are pure: a copy of the state gives the same values
    CHECK(Waves::outputs(params, input, copy).elevation_m[1] == out.elevation_m[1]);
  }
  // default: one probe at the origin
  const Waves::Params defaults = Waves::make_params(jonswap(1.0, 6.0, 2.0, 100.0, 600.0, 0.25));
  REQUIRE(Waves::channels(defaults).size() == 1);
  CHECK(defaults.probes->point(0).norm() == 0.0);
}

TEST_CASE("the seed's load cases at OC3 depth reproduce Hs", "[verification][waves]") {
  // seed 000 Table 4.2: typical Hs 1.8 m, Tp 6.1 s; extreme Hs 11.3 m, Tp 14.4 s; JONSWAP with
  // the IEC default γ, OC3 depth 320 m, 1-hour records at dt 0.25 s. Hs within 2 % (issue).
  struct Case {
    double hs, tp, gamma;
  };
  for (const Case& c : {Case{1.8, 6.1, 1.684}, Case{11.3, 14.4, 2.279}}) {
    WaveParams p = jonswap(c.hs, c.tp, 1.0, 320.0, 3600.0, 0.25, 1);
    p.gamma.reset();
    const WaveField field(p);
    CHECK(field.peak_shape() == Approx(c.gamma).epsilon(1e-3));
    const std::vector<double> eta = field.elevation_series(0.0, 0.0);
    double var = 0.0;
    for (double v : eta) var += v * v;
    var /= static_cast<double>(eta.size());
    CHECK(4.0 * std::sqrt(var) == Approx(c.hs).epsilon(0.02));
  }
}
