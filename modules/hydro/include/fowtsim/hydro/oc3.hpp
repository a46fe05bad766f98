#pragma once
// The OC3-Hywind spar as hydro Params: geometry, drag coefficient and linear extras transcribed
// from the OpenFAST r-test HydroDyn deck `5MW_OC3Spar_DLL_WTurb_WavesIrr` (Jonkman, NREL/TP-500-
// 47266). That deck takes added mass from WAMIT (SimplCa = 0, PropPot = TRUE); a Morison-only
// model needs its own C_a, here the slender circular-cylinder value C_a = 1 (DNV-RP-C205 App. D).
#include "fowtsim/hydro/params.hpp"

namespace fowtsim::hydro {

// Members: z −120 → −12 m (D 9.4 m), −12 → −4 m (taper 9.4 → 6.5 m), −4 → 10 m (D 6.5 m);
// C_d 0.6; axial coefficients of the deck (C_a,ax = C_d,ax = 0, C_p,ax = 1); AddCLin(6,6) =
// 9.834e7 N·m/rad; AddBLin diag(1e5, 1e5, 1.3e5, 0, 0, 1.3e7); ρ 1025 kg/m³, g 9.80665 m/s².
// strips_* are the strip counts of the three members (README "Performance" for the choice).
Params oc3_hywind_params(int strips_lower = 48, int strips_taper = 4, int strips_upper = 4);

inline constexpr double kOc3DisplacedVolume_m3 = 8029.21;    // HydroDyn PtfmVol0 (WAMIT)
inline constexpr double kOc3HeaveStiffness_N_m = 332941.0;    // WAMIT Spar.hst C33 · ρ g
inline constexpr double kOc3RollPitchStiffness_N_m_rad = -4.9992e9;  // C44 = C55 · ρ g (waterplane + COB)

}  // namespace fowtsim::hydro
