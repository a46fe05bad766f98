// advance() and outputs() must not touch the heap (brief: "no heap allocation in the step").
#include <catch2/catch.hpp>

#include "fowtsim/testing/allocation_counter.hpp"

#include "fowtsim/flexbody/blade_deck.hpp"
#include "fowtsim/multibody/multibody.hpp"
#include "fowtsim/multibody/oc3.hpp"
#include "test_support.hpp"

using fowtsim::testing::allocations;
using fowtsim::testing::counting;
using namespace fowtsim;
using namespace fowtsim::multibody;

namespace {
class SpringProvider : public LoadProvider {
 public:
  void loads(double, const State& s, AppliedLoads& out) override {
    out.platform_force_N = -41180.0 * s.position_m;
    out.platform_added_mass.diagonal().setConstant(1.0e6);
    out.generator_torque_N_m = 4.0e4;
  }
  YawMotion nacelle_yaw(double t) override { return {0.01 * t, 0.01, 0.0}; }
};
}  // namespace

TEST_CASE("a multibody step and its outputs allocate nothing", "[unit][multibody]") {
  Params p = oc3_hywind_params();
  p.nacelle.yaw_prescribed = true;
  p.initial_conditions.rotor_speed_rpm = 12.1;
  const Model model = make_model(p);
  State s = Multibody::make_state(model);
  SpringProvider provider;
  AppliedLoads loads;
  allocations = 0;
  counting = true;
  double sink = 0.0;
  for (int k = 0; k < 50; ++k) {
    Multibody::advance(model, provider, k * 0.05, 0.05, s);
    sink += Multibody::outputs(model, loads, s).channels[0];
  }
  counting = false;
  CHECK(allocations == 0);
  CHECK(std::isfinite(sink));
}

TEST_CASE("channels() and the Output channel array agree in size", "[unit][multibody]") {
  const Model model = make_model(oc3_hywind_params());
  CHECK(Multibody::channels(model).size() == static_cast<std::size_t>(kChannelCount + 3));  // + TwrClrnc1–3 (rigid blades)
  Params p = oc3_hywind_params();
  set_oc3_flexible_tower(p);
  p.tower.gauge_heights_m = {0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 77.0};
  p.rotor.rayleigh_ritz_blade = flexbody::read_elastodyn_blade(FOWTSIM_SOURCE_DIR "/inputs/nrel5mw/blade_elastodyn.yaml");
  p.rotor.blade_gauge_fractions = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8};
  CHECK(Multibody::channels(make_model(p)).size() ==
        static_cast<std::size_t>(kMaxChannelCount));  // every capacity used: 9 tower gauges, 3 clearances, 3 RR blades with 9 gauges
}

TEST_CASE("a flexible-tower step with Rayleigh-Ritz blades and its outputs allocate nothing",
          "[unit][multibody][flexible_tower][rr_blades]") {
  Params p = oc3_hywind_params();
  set_oc3_flexible_tower(p);
  p.rotor.rayleigh_ritz_blade = flexbody::read_elastodyn_blade(FOWTSIM_SOURCE_DIR "/inputs/nrel5mw/blade_elastodyn.yaml");
  p.rotor.blade_station_spans_m = {10.0, 30.0, 50.0};
  p.rotor.blade_gauge_fractions = {0.3};
  p.nacelle.yaw_prescribed = true;
  p.initial_conditions.rotor_speed_rpm = 12.1;
  p.initial_conditions.tower_top_deflection_m = {0.2, -0.05};
  p.tower.gauge_heights_m = {0.0, 36.86};
  const Model model = make_model(p);
  State s = Multibody::make_state(model);
  SpringProvider provider;
  AppliedLoads loads;
  loads.tower_loads[0] = {30.0, Vec3(5.0e3, 1.0e3, 0.0)};  // a tower load: its point, the gauges' filter
  loads.tower_load_count = 1;
  loads.blade_station_load_count = 4;  // a load at every blade station (the tip's included)
  for (auto& blade : loads.blade_station_loads)
    for (auto& at : blade) at = {Vec3(1.0e3, 2.0e2, 0.0), Vec3(0.0, 0.0, 50.0)};
  allocations = 0;
  counting = true;
  double sink = 0.0;
  for (int k = 0; k < 50; ++k) {
    Multibody::advance(model, provider, k * 0.05, 0.05, s);
    sink += Multibody::outputs(model, loads, s).channels[kChannelCount];  // TTDspFA
  }
  counting = false;
  CHECK(allocations == 0);
  CHECK(std::isfinite(sink));
}
