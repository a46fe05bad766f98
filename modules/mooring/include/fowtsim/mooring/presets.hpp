#pragma once
// Published mooring systems, transcribed (numbers are facts; sources in the .cpp).
#include "fowtsim/mooring/params.hpp"

namespace fowtsim::mooring {

// OC3-Hywind (Jonkman NREL/TP-500-47266; OpenFAST r-test deck 5MW_OC3Spar_DLL_WTurb_WavesIrr, MAP
// input): three catenary lines at headings 0°, 120°, 240°, the delta connection replaced by the
// yaw spring 9.834e7 N·m/rad. Water depth 320 m, ρ = 1025 kg/m³, g = 9.80665 m/s² (the .fst).
MooringParams oc3_hywind_mooring();

// Seed 000 §4.5.1 taut-leg system: four massless springs, anchors 804.7 m from the spar axis at
// 320 m depth, EA = 384,243,000 N, yaw spring 98,340,000 N·m/rad. The seed does not state the
// fairlead radius, the headings, the unstretched length or a pretension, so the caller gives the
// fairlead position (the seed: 7.6 m below the spar/tower centre of mass, on the spar surface)
// and the pretension at zero offset; headings are taken as 0°, 90°, 180°, 270° (Fig. 4.3 is
// missing from the extracted text).
MooringParams seed_taut_mooring(double fairlead_z_m, double fairlead_radius_m, double pretension_N);

}  // namespace fowtsim::mooring
