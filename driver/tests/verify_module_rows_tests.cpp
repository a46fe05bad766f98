// The rows of `fowtsim verify aero|wind|multibody|control|flexbody|slender|pipe` (cli/verify_aero_wind.cpp,
// cli/verify_multibody_control.cpp, cli/verify_flexbody.cpp: each row with its bound and the reason for it) all pass, and
// none goes missing: the row counts are fixed, with or without the reference data of ../shared.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "verify/verify_cases.hpp"
#include "fowtsim/testing/skip.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

// Runs one case through the command's dispatcher (the name must be known to it) and checks every
// row; `rows_without_reference` rows need nothing from ../shared, `reference_rows` more come from it.
void check_case(const std::string& name, std::size_t rows_without_reference, std::size_t reference_rows) {
  const std::filesystem::path shared = FOWTSIM_SHARED_DIR;
  const bool have_reference = std::filesystem::is_directory(shared / "reference");
  set_shared_dir(shared);
  const std::vector<VerificationRow> rows = run_verification_case(name, stdout);
  CHECK(rows.size() == rows_without_reference + (have_reference ? reference_rows : 0));
  for (const VerificationRow& r : rows) {
    INFO(r.case_name << ": " << r.metric << " = " << r.value << " (" << r.tolerance << ", " << r.source << ")");
    CHECK(r.case_name == name);
    CHECK(r.pass);
  }
}

}  // namespace

TEST_CASE("fowtsim verify aero: Cp peak, AeroDyn operating points, momentum balance, tower potential flow",
          "[verification][aero]") {
  // Cp peak and its λ; momentum thrust and torque; tower potential flow. With ../shared: five
  // rotor loads, α, induction, RtSpeed, RtVAvgxh, RtTSR, RtAeroCq, RtSkew, the node loads and
  // convergence against AeroDyn's seven operating points.
  check_case("aero", 5, 14);
}

TEST_CASE("fowtsim verify wind: IEC σ, events, EWM, generated σ, sampler coherence, TurbSim files", "[verification][wind]") {
  // NTM and ETM σ1, the five IEC events, EWM σ1 and its generated hub σ, generated σ u/v/w, three
  // sampler methods. With ../shared: the 60 s file against Wind1VelX/Y/Z and the 600 s file's hub
  // statistics against TurbSim's summary.
  check_case("wind", 15, 7);
}

TEST_CASE("fowtsim verify multibody: precession, heave period, conservation, OC3 masses, RR blades", "[verification][multibody]") {
  // 10 rigid-chain rows, then the RR blade's rotating frequencies and the flexible turbine's 3 invariants.
  check_case("multibody", 14, 0);
}

TEST_CASE("fowtsim verify control: closed-loop pitch, torque schedule, speed filter", "[verification][control]") {
  check_case("control", 12, 0);
}

TEST_CASE("fowtsim verify flexbody: seed 002's Rayleigh–Ritz bodies, Sec. 5.1–5.5 and 6, the RR blade", "[verification][flexbody]") {
  // Sec. 5.1 (4 closed forms, top-mass modes, 3 buckling rows), welib's beam (3), Table 1 (7 cases ×
  // δf_2, δf_4 and the RR bound), Sec. 6 (7 printed entries), Sec. 5.3 torsion (5), Kane's spin-up (3),
  // the pre-bent spin-up of Sec. 5.4 (8), ElastoDyn's RR blade against its summary and our MBBT
  // blade (7).
  check_case("flexbody", 62, 0);
}

TEST_CASE("fowtsim verify slender: seed 004's riser and OC3 tower, modes, FD vs TD, EI vs inertia relief", "[verification][slender]") {
  // Riser modes (1), FD vs TD amplitude for the tower and the riser (2 × 2), riser RMS (1), EI vs IR (1).
  check_case("slender", 7, 0);
}

TEST_CASE("fowtsim verify pipe: seed Table 3.1 and the classical thresholds of pipes conveying fluid",
          "[verification][pipe]") {
  // Table 3.1 with flow: modes 1–3 (3), the seed's flux (1), the first frequency's fall (1);
  // rotating: at rest, flap rise, lead-lag rise (3); Table 3.2, two parameter sets (2); the seed's
  // white-noise method (3); cantilever flutter, two divergences (3); the riser's cases (3).
  check_case("pipe", 19, 0);
}

TEST_CASE("fowtsim verify screening: OC3 free-floating frequencies, operating points, FD/TD std", "[verification][screening]") {
  // Operating points (2 pitch + 3 rotor speeds), FD/TD std of heave, pitch, TwrBsMyt (3); with the
  // WAMIT files beside the reference data the four free-floating frequencies.
  check_case("screening", 8, 4);
}

TEST_CASE("fowtsim verify all includes the module cases", "[unit]") {
  const std::vector<std::string> names = verification_case_names();
  for (const char* name : {"aero", "wind", "multibody", "control", "flexbody", "slender", "pipe", "screening"}) {
    INFO(name);
    CHECK(std::find(names.begin(), names.end(), name) != names.end());
  }
}
