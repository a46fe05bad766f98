#pragma once
// The `structure:` deck section ↔ multibody::Params, key for key (modules/multibody/params.hpp).
#include "fowtsim/io/schema.hpp"
#include "fowtsim/multibody/params.hpp"

namespace fowtsim::driver {

io::Schema structure_schema();
multibody::Params structure_params(const io::ValidatedDeck& section);

}  // namespace fowtsim::driver
