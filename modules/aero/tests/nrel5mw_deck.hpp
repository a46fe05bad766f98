#pragma once
// Test-only reader of the NREL 5MW aero deck (inputs/nrel5mw/aero.yaml and its airfoils.yaml):
// the same YAML the driver reads, mapped onto aero::Params key for key. The driver's deck reader
// (io module) will replace this; it exists so the tests use the deck as their single source.
#include <filesystem>

#include "fowtsim/aero/params.hpp"

namespace fowtsim::aero::testing {

// Reads <source>/inputs/nrel5mw/aero.yaml; throws std::runtime_error on a missing key.
Params load_nrel5mw_deck();
Params load_aero_deck(const std::filesystem::path& aero_yaml);

}  // namespace fowtsim::aero::testing
