#pragma once
// The controller of a turbine deck, built-in (NREL 5MW baseline law) or external (a Bladed DISCON
// library), behind one interface, with the control and fault events of the deck (shutdowns, grid
// loss, brake, pitch faults, start-up; control/events.hpp) on top of either. It runs at the large
// step (sample and hold): its demands are held over the step.
#include <variant>

#include "decks/controller_deck.hpp"
#include "fowtsim/control/baseline_controller.hpp"
#include "fowtsim/control/events.hpp"
#include "fowtsim/control/external_controller.hpp"

namespace fowtsim::driver {

class TurbineController {
 public:
  // What changes (a part of the scene state). A DISCON library's own state lives in the library:
  // copying Data does not copy it, so only the built-in law can be checkpointed or retried.
  struct Data {
    std::variant<control::BaselineState, control::ExternalController::State> state;
    control::ControllerOutput output{};  // the demands of the last call, events applied
    control::EventState events{};        // which events fired and when, the contactor, the brake
  };

  explicit TurbineController(ControllerSetup setup) : params_(std::move(setup.law)), events_(std::move(setup.events)) {}
  Data make_data() const;
  // The law at time t, then the events (control::apply_events) on its demands.
  void advance(const control::ControllerInput& u, double t, double dt, Data& d) const;
  bool can_checkpoint() const { return std::holds_alternative<control::BaselineParams>(params_); }
  // The last call a DISCON library gets (status −1: it closes its files); nothing for the built-in law.
  void finish(double t, Data& d) const;
  const control::EventsParams& events() const { return events_; }
  // The HSS brake torque at time t of the brake state in d [N·m, ≥ 0] (ServoDyn HSSBrMode 1 ramp).
  double brake_torque_N_m(const Data& d, double t) const {
    return control::brake_torque_N_m(events_.brake, d.events.brake_engaged_at_s, t);
  }

 private:
  ControllerParams params_;
  control::EventsParams events_;
};

// Field list (core/fields.hpp).
template <class Archive>
void fields(Archive& a, TurbineController::Data& d) {
  a.io(d.state, d.output, d.events);
}

}  // namespace fowtsim::driver
