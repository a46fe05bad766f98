#pragma once
// `fowtsim verify aero|wind|multibody|control|flexbody`: the headline checks of each module's verification
// tests (issue 16), computed through the modules' public verification headers
// (fowtsim/<module>/verification.hpp) that the module tests use too. Each row holds its bound and
// the reason for it; the rows against OpenFAST or TurbSim files are left out when ../shared is
// absent (the detail output says so).
#include <cstdio>
#include <vector>

#include "verify/reports.hpp"

namespace fowtsim::driver {

// NREL 5MW Cp–λ peak, rigid rotor against OpenFAST AeroDyn at its seven operating points, the
// momentum balance of converged sections, the tower potential flow.
std::vector<VerificationRow> verify_aero(std::FILE* out);
// IEC NTM/ETM σ, generated fields' σ u, v, w, the sampler's coherence, TurbSim's OC3 files.
std::vector<VerificationRow> verify_wind(std::FILE* out);
// Gyroscopic precession, heave period on springs, conservation of the free OC3 system, OC3 masses.
std::vector<VerificationRow> verify_multibody(std::FILE* out);
// Closed-loop steady pitch against the operating table, torque schedule, speed filter.
std::vector<VerificationRow> verify_control(std::FILE* out);
// Seed 002's Rayleigh–Ritz bodies (modules/flexbody): Sec. 5.1 closed forms, top-mass modes and
// buckling, welib's uniform beam, Table 1, Sec. 6's M_q/K_q, Sec. 5.3 torsion, Sec. 5.2 Kane's spin-up.
std::vector<VerificationRow> verify_flexbody(std::FILE* out);
// Seed 004's slender bodies (modules/slender) on inputs/slender/: riser modes against the closed
// form, FD vs TD (drag linearisation) in a regular wave and a JONSWAP sea, EI v'' vs inertia relief.
std::vector<VerificationRow> verify_slender(std::FILE* out);
// Issue 25's screening of the floating turbine: OC3 free-floating frequencies against OpenFAST's free
// decays, operating points, FD/TD std over a periodic sea; prints the time per screening case.
std::vector<VerificationRow> verify_screening(std::FILE* out);

}  // namespace fowtsim::driver
