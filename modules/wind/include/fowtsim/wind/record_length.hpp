#pragma once
// Whether a run outlasts its turbulence box. By Taylor's frozen turbulence a rotor point at
// wind-frame x reads the box at t' = t + (X0 − x)/U_hub (full_field.hpp): the points upwind of the
// tower read ahead of t. A periodic box (ours, TurbSim's id 8) then wraps around without a word —
// the wind at t repeats that at t − T — and a non-periodic one (id 7) ends, where the run stops as
// InflowWind does. The box must cover t_end + (X0 + reach)/U_hub, `reach` the farthest a rotor point
// gets upwind of the tower axis.
#include <optional>
#include <string>

#include "fowtsim/wind/wind_field.hpp"

namespace fowtsim::wind {

// A warning for the run summary when the field's full field (if any) is shorter than a run to
// t_end_s needs; nullopt for the analytic profiles and for a box long enough.
std::optional<std::string> box_length_warning(const WindField& field, double t_end_s, double upwind_reach_m);

}  // namespace fowtsim::wind
