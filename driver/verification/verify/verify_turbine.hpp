#pragma once
// `fowtsim verify turbine-validation` and `turbine-oc3`: the floating turbine with flexible MBBT
// blades against OpenFAST v5 with BeamDyn blades (issue 12, verifications 3 and 4). Each row
// holds its bound and the reason for it; the driver tests assert that every row passes.
#include <cstdio>
#include <filesystem>
#include <vector>

#include "verify/reports.hpp"

namespace fowtsim::driver {

// Seed 000 §4.5.3 (inputs/oc3_hywind/seed_validation_surge1000.yaml) against
// openfast-runs/seed_validation_surge1000/v1_surge1000_BD, statistics over 50–100 s.
std::vector<VerificationRow> verify_turbine_validation(std::FILE* out);

// The OC3 load case on OpenFAST's TurbSim file and its replayed sea (Wave1Elev) against
// openfast-runs/oc3_spar_wturb_wavesirr …_BD.out, statistics over 10–60 s.
std::vector<VerificationRow> verify_turbine_oc3(std::FILE* out);

// OC3-Hywind free decay (rigid multibody, Morison hydro, hydrostatics, catenary; issue 6
// verification 4): the four natural periods against the published OC3 values, and against the
// OpenFAST v5 free-decay runs when the reference data are there.
std::vector<VerificationRow> verify_free_decay(std::FILE* out);

}  // namespace fowtsim::driver
