#pragma once
// The controller of a turbine deck, built-in (NREL 5MW baseline law) or external (a Bladed DISCON
// library), behind one interface. It runs at the large step (sample and hold): its demands are
// held over the step.
#include <variant>

#include "decks/controller_deck.hpp"
#include "fowtsim/control/baseline_controller.hpp"
#include "fowtsim/control/external_controller.hpp"

namespace fowtsim::driver {

class TurbineController {
 public:
  // What changes (a part of the scene state). A DISCON library's own state lives in the library:
  // copying Data does not copy it, so only the built-in law can be checkpointed or retried.
  struct Data {
    std::variant<control::BaselineState, control::ExternalController::State> state;
    control::ControllerOutput output{};  // the demands of the last call
  };

  explicit TurbineController(ControllerParams params) : params_(std::move(params)) {}
  Data make_data() const;
  void advance(const control::ControllerInput& u, double t, double dt, Data& d) const;
  bool can_checkpoint() const { return std::holds_alternative<control::BaselineParams>(params_); }
  // The last call a DISCON library gets (status −1: it closes its files); nothing for the built-in law.
  void finish(double t, Data& d) const;

 private:
  ControllerParams params_;
};

// Field list (core/fields.hpp).
template <class Archive>
void fields(Archive& a, TurbineController::Data& d) {
  a.io(d.state, d.output);
}

}  // namespace fowtsim::driver
