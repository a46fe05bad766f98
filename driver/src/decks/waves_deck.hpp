#pragma once
// The `waves:` deck section ↔ waves::WaveParams, key for key (modules/waves/wave_params.hpp).
#include "fowtsim/io/schema.hpp"
#include "fowtsim/waves/wave_params.hpp"

namespace fowtsim::driver {

io::Schema waves_schema();
waves::WaveParams wave_params(const io::ValidatedDeck& section);

}  // namespace fowtsim::driver
