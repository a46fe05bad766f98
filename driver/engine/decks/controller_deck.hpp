#pragma once
// The `controller:` deck section: the built-in NREL 5MW baseline law (type baseline, keys one to
// one onto control::BaselineParams) or an external Bladed-style DISCON library (type discon).
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
