#pragma once
// Whether a run outlasts its turbulence box. By Taylor's frozen turbulence a rotor point at
// wind-frame x reads the box at t' = t + (X0 − x)/U_hub (full_field.hpp): the points upwind of the
// tower read ahead of t. A periodic box (ours, TurbSim's id 8) then wraps around without a word —
// the wind at t repeats that at t − T — and a non-periodic one (id 7) ends, where the run stops as
// InflowWind does. The box must cover t_end + (X0 + reach)/U_hub, `reach` the farthest a rotor point
// gets upwind of the tower axis. A uniform wind file shorter than the run holds its last row (as
// InflowWind does), and an event that starts at or after the run's end never acts: both are said.
#include <optional>
#include <string>

#include "fowtsim/wind/wind_field.hpp"

namespace fowtsim::wind {

// A warning for the run summary when the field's full field (if any) is shorter than a run to
// t_end_s needs, or its uniform wind file ends before t_end_s; nullopt for the analytic profiles
// and for a record long enough.
std::optional<std::string> box_length_warning(const WindField& field, double t_end_s, double upwind_reach_m);

// A warning when the deck's IEC event starts at or after t_end_s (it would add nothing to the run).
std::optional<std::string> event_timing_warning(const WindField& field, double t_end_s);

}  // namespace fowtsim::wind
