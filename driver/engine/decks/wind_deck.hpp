#pragma once
// The `wind:` deck section ↔ wind::WindParams, key for key (modules/wind/params.hpp).
#include "fowtsim/io/schema.hpp"
#include "fowtsim/wind/params.hpp"

namespace fowtsim::driver {

io::Schema wind_schema();
// A relative `file` is resolved against the directory of the deck file that names it.
wind::WindParams wind_params(const io::ValidatedDeck& section);

}  // namespace fowtsim::driver
