#pragma once
// The `hydro:` deck section ↔ hydro::Params, key for key (modules/hydro/README.md).
#include "fowtsim/hydro/params.hpp"
#include "fowtsim/io/schema.hpp"

namespace fowtsim::driver {

io::Schema hydro_schema();
// Reads a validated `hydro:` section; a value the module rejects is reported with file:line.
hydro::Params hydro_params(const io::ValidatedDeck& section);

}  // namespace fowtsim::driver
