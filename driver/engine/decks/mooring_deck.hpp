#pragma once
// The `mooring:` deck section ↔ mooring::MooringParams, key for key (modules/mooring/params.hpp).
#include "fowtsim/io/schema.hpp"
#include "fowtsim/mooring/params.hpp"

namespace fowtsim::driver {

io::Schema mooring_schema();
mooring::MooringParams mooring_params(const io::ValidatedDeck& section);

}  // namespace fowtsim::driver
