#pragma once
// The `aero:` and `airfoils:` deck sections ↔ aero::Params (modules/aero/README.md "Deck mapping").
// Blade rows mix numbers and an airfoil name, so rows are read as scalars and converted here with
// file:line on a bad entry.
#include "fowtsim/aero/params.hpp"
#include "fowtsim/io/schema.hpp"

namespace fowtsim::driver {

io::Schema aero_schema();
io::Schema airfoils_schema();
// `deck` holds both `aero` and `airfoils` at its top level.
aero::Params aero_params(const io::ValidatedDeck& deck);

}  // namespace fowtsim::driver
