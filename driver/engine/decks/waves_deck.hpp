#pragma once
// The `waves:` deck section ↔ waves::WaveParams, key for key (modules/waves/wave_params.hpp).
#include "fowtsim/io/schema.hpp"
#include "fowtsim/waves/wave_params.hpp"

namespace fowtsim::driver {

io::Schema waves_schema();
// model elevation_series: reads `file` (relative to the directory of the deck file that names it)
// into WaveParams::elevation_record — two columns (time s, elevation m), or the Wave1Elev channel of
// an OpenFAST .out/.outb or our .h5 output; InputError naming file and line on a bad record.
waves::WaveParams wave_params(const io::ValidatedDeck& section);

}  // namespace fowtsim::driver
