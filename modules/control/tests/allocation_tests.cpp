// The per-step calls (advance, outputs, channel_values) of both controllers must not touch the
// heap (fixed-size State and Output; the DLL call itself included).
#include <array>
#include <cmath>

#include <catch2/catch.hpp>

#include "fowtsim/testing/allocation_counter.hpp"

#include "fowtsim/control/baseline_controller.hpp"
#include "fowtsim/control/events.hpp"
#include "fowtsim/control/external_controller.hpp"
#include "fowtsim/control/presets.hpp"

using fowtsim::testing::allocations;
using fowtsim::testing::counting;
using namespace fowtsim::control;

namespace {

template <class Controller>
long count_allocations(const typename Controller::Params& p) {
  typename Controller::State s = Controller::make_state(p);
  std::array<double, 6> values{};
  ControllerInput u;
  Controller::advance(p, u, 0.0, 0.0125, s);  // first call outside the count (may set things up)
  allocations = 0;
  counting = true;
  for (int k = 1; k < 2000; ++k) {
    u.generator_speed_rad_s = 115.0 + 12.0 * std::sin(0.005 * k);
    Controller::advance(p, u, 0.0125 * k, 0.0125, s);
    const ControllerOutput y = Controller::outputs(p, u, s);
    Controller::channel_values(p, y, values);
    u.blade_pitch_rad = y.blade_pitch_rad;
  }
  counting = false;
  return allocations;
}

}  // namespace

TEST_CASE("controller step calls allocate nothing", "[unit][control]") {
  CHECK(count_allocations<BaselineController>(nrel5mw_land_baseline()) == 0);
  CHECK(count_allocations<BaselineController>(oc3_hywind_baseline()) == 0);
  ExternalSettings e;
  e.library_path = FOWTSIM_TEST_DISCON;
  e.infile = "oc3_hywind";
  const ExternalController::Params p = ExternalController::make_params(e);
  CHECK(count_allocations<ExternalController>(p) == 0);
}

TEST_CASE("control events allocate nothing per call", "[unit][control]") {
  // The events run after the law at every large step (events.hpp): fixed-size EventState only.
  const BaselineParams p = nrel5mw_land_baseline();
  EventsParams events;
  EventParams loss, stuck, brake;
  loss.type = EventType::grid_loss;
  loss.at_s = 0.5;
  loss.pitch_rate_rad_s = stuck.pitch_rate_rad_s = brake.pitch_rate_rad_s = 0.14;
  stuck.type = EventType::pitch_stuck;
  stuck.at_s = 1.0;
  stuck.blade = 2;
  brake.type = EventType::brake;
  brake.at_s = 2.0;
  events.events = {loss, stuck, brake};
  BaselineState s = BaselineController::make_state(p);
  EventState e = make_event_state(events);
  ControllerInput u;
  ControllerOutput y;
  allocations = 0;
  counting = true;
  for (int k = 0; k < 400; ++k) {
    u.generator_speed_rad_s = 125.0 + std::sin(0.01 * k);
    event_status(e, u);
    BaselineController::advance(p, u, 0.0125 * k, 0.0125, s);
    y = BaselineController::outputs(p, u, s);
    apply_events(events, u, 0.0125 * k, 0.0125, e, y);
    u.blade_pitch_rad = y.blade_pitch_rad;
  }
  counting = false;
  CHECK(allocations == 0);
  CHECK(y.blade_pitch_rad[2] == e.fault_from_rad[2]);
}
