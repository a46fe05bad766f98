#pragma once
// The `controller:` deck section: the built-in controller (type baseline, keys one to one onto
// control::BaselineParams: the NREL 5MW baseline laws, or ServoDyn's simple modes with `generator:
// simple_vs` + `simple_vs: {…}` and `pitch: fixed`) or an external Bladed-style DISCON library
// (type discon).
#include <variant>

#include "fowtsim/control/baseline_controller.hpp"
#include "fowtsim/control/events.hpp"
#include "fowtsim/control/external_controller.hpp"
#include "fowtsim/io/schema.hpp"

namespace fowtsim::driver {

io::Schema controller_schema();
using ControllerParams = std::variant<control::BaselineParams, control::ExternalController::Params>;
// A relative `library` is resolved against the directory of the deck file that names it.
ControllerParams controller_params(const io::ValidatedDeck& section);

// The law and the deck's control events (`operating_mode`, `events`, `brake`), their defaults taken
// from the law: pitch rates its pitch-rate limit, feather its maximum pitch, a runaway's target its
// minimum pitch, the generator's (dis)connection speed its cut-in speed.
struct ControllerSetup {
  ControllerParams law;
  control::EventsParams events;
};
ControllerSetup controller_setup(const io::ValidatedDeck& section);

}  // namespace fowtsim::driver
