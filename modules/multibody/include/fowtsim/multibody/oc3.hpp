#pragma once
// The NREL 5-MW turbine on the OC3-Hywind spar as multibody Params, transcribed from the
// ElastoDyn inputs of the OpenFAST r-test deck 5MW_OC3Spar_DLL_WTurb_WavesIrr (platform, tower
// table, nacelle, hub, drivetrain) and NREL/TP-500-38060 Table 2-1 (blade mass 17,740 kg, first
// mass moment 363,231 kg·m, second mass moment 11,776,047 kg·m² about the root). The same numbers
// are in inputs/oc3_hywind/structure.yaml; a test checks that they agree.
#include "fowtsim/multibody/params.hpp"

namespace fowtsim::multibody {

// Rigid blades, flexible drivetrain, fixed yaw, all initial conditions zero.
Params oc3_hywind_params();

// Switches on the flexible tower of the OC3-Hywind deck (ElastoDyn_Tower.dat: TwFAStif, TwSSStif,
// TwFAM1Sh … TwSSM2Sh, TwrFADmp, TwrSSDmp; 2 fore-aft + 2 side-side modes, 1 % damping each).
void set_oc3_flexible_tower(Params& p);

}  // namespace fowtsim::multibody
