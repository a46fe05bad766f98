#pragma once
// The `controller:` deck section: the built-in controller (type baseline, keys one to one onto
// control::BaselineParams: the NREL 5MW baseline laws, or ServoDyn's simple modes with `generator:
// simple_vs` + `simple_vs: {…}` and `pitch: fixed`) or an external Bladed-style DISCON library
// (type discon).
#include <variant>

#include "fowtsim/control/baseline_controller.hpp"
#include "fowtsim/control/external_controller.hpp"
#include "fowtsim/io/schema.hpp"

namespace fowtsim::driver {

io::Schema controller_schema();
using ControllerParams = std::variant<control::BaselineParams, control::ExternalController::Params>;
// A relative `library` is resolved against the directory of the deck file that names it.
ControllerParams controller_params(const io::ValidatedDeck& section);

}  // namespace fowtsim::driver
