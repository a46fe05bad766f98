#include "scenes/turbine_controller.hpp"

#include <type_traits>

namespace fowtsim::driver {

TurbineController::Data TurbineController::make_data() const {
  Data d;
  if (const auto* p = std::get_if<control::BaselineParams>(&params_)) d.state = control::BaselineController::make_state(*p);
  else d.state = control::ExternalController::make_state(std::get<control::ExternalController::Params>(params_));
  d.events = control::make_event_state(events_);
  return d;
}

void TurbineController::advance(const control::ControllerInput& measured, double t, double dt, Data& d) const {
  control::ControllerInput u = measured;
  control::event_status(d.events, u);  // what a DISCON sees in records 35 and 36
  std::visit(
      [&](const auto& p) {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, control::BaselineParams>) {
          auto& s = std::get<control::BaselineState>(d.state);
          control::BaselineController::advance(p, u, t, dt, s);
          d.output = control::BaselineController::outputs(p, u, s);
        } else {
          auto& s = std::get<control::ExternalController::State>(d.state);
          control::ExternalController::advance(p, u, t, dt, s);
          d.output = control::ExternalController::outputs(p, u, s);
        }
      },
      params_);
  control::apply_events(events_, u, t, dt, d.events, d.output);
}

void TurbineController::finish(double t, Data& d) const {
  if (const auto* p = std::get_if<control::ExternalController::Params>(&params_))
    control::ExternalController::finish(*p, t, std::get<control::ExternalController::State>(d.state));
}

}  // namespace fowtsim::driver
