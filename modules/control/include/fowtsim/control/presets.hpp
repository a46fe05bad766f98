#pragma once
// Published parameter sets of the NREL 5-MW baseline controller (constants transcribed from
// ../shared/reference/PUBLISHED.md "Baseline controller constants"). The YAML decks
// inputs/nrel5mw/controller_land.yaml and inputs/oc3_hywind/controller.yaml hold the same numbers
// (a test checks that they agree). Standard library only (compiled into the test DISCON too).
#include <optional>
#include <string_view>

#include "fowtsim/control/baseline_params.hpp"

namespace fowtsim::control {

// Land-based turbine (Jonkman et al., NREL/TP-500-38060, Ch. 7): constant power in region 3,
// sample time 0.000125 s of the land-based DISCON.
BaselineParams nrel5mw_land_baseline();

// OC3-Hywind (Jonkman, NREL/TP-500-47266): detuned pitch gains K_P = 0.006275604 s,
// K_I = 0.0008965149, constant torque in region 3, sample time 0.00125 s of the OC3 DISCON.
BaselineParams oc3_hywind_baseline();

// "nrel5mw_land" | "oc3_hywind" → the set above; empty for any other name.
std::optional<BaselineParams> baseline_preset(std::string_view name);

}  // namespace fowtsim::control
