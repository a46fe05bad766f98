#pragma once
// The inflow and sea records a run reads against the run's length: a turbulence box or a wave
// record shorter than the run repeats (or, a non-periodic box, ends) without a word from the
// modules themselves (wind/record_length.hpp, waves/record_length.hpp). Said up front, in the
// summary and the outputs' warnings, even of a run that then fails.
#include <string>
#include <vector>

#include "fowtsim/waves/wave_params.hpp"
#include "fowtsim/wind/wind_field.hpp"

namespace fowtsim::driver {

// `wind`, `waves`: the scene's, or null without them. `upwind_reach_m`: how far a rotor point gets
// upwind of the tower axis. `t_end_s`: the end of the run (it starts at t = 0).
std::vector<std::string> record_length_warnings(const wind::WindField* wind, double upwind_reach_m, const waves::WaveParams* waves,
                                                double t_end_s);

}  // namespace fowtsim::driver
