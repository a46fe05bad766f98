// BeamDyn reference cases rerun with the MBBT beam through `fowtsim run bd_driver.inp`, compared
// with BeamDyn's outputs in ../shared/reference (skipped when that is absent). Tolerances state
// what limits the agreement: our discretisation error, or a known limit of the reference.
#include <algorithm>
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "verify/beamdyn_comparison.hpp"
#include "beamdyn/beamdyn_setup.hpp"
#include "fowtsim/beam/modal.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/testing/skip.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

std::filesystem::path rtest(const std::string& name) {
  return testing::shared_dir_or_skip() / "reference/r-test/modules/beamdyn" / name;
}

BeamDynRun run_rtest(const std::string& name, int segments) {
  return run_beamdyn_reference(rtest(name) / "bd_driver.inp", rtest(name) / "bd_driver.out", segments,
                               testing::scratch_dir("beamdyn_" + name) / name);
}

}  // namespace

TEST_CASE("BeamDyn isotropic roll-up: tip deflection and rotation", "[verification][beamdyn]") {
  const BeamDynRun run = run_rtest("bd_isotropic_rollup", 64);
  // The exact answer is an arc of 72° (BeamDyn reproduces it to 8 digits). Second-order finite
  // volumes at 64 segments: measured 1.6e-5 (y), 5e-5 (z), 1e-9 (rotation) relative.
  for (const char* ch : {"TipTDyr", "TipTDzr", "TipRDxr"}) {
    INFO(ch << ": ours " << final_value(run.ours, ch) << ", BeamDyn " << final_value(run.reference, ch));
    CHECK(std::abs(final_value(run.ours, ch) - final_value(run.reference, ch)) < 2e-4 * std::abs(final_value(run.reference, ch)));
  }
}

TEST_CASE("BeamDyn 45-degree curved beam: within the spread of the two BeamDyn outputs", "[verification][beamdyn]") {
  const BeamDynRun run = run_rtest("bd_curved_beam", 64);
  const io::ChannelTable v5 = io::read_channels(testing::shared_dir_or_skip() /
                                                "reference/openfast-runs/bd_driver_rtest/modules/beamdyn/bd_curved_beam/bd_driver.out");
  // The 2019 r-test output and the OpenFAST v5 rerun differ by up to 2 % (TipTDxr) — the
  // reference is that band. Ours must lie in it, give or take 1e-3 of the value (our measured
  // distance to the v5 rerun is ≤ 5e-4 relative on every channel).
  for (const char* ch : {"TipTDxr", "TipTDyr", "TipTDzr", "TipRDxr", "TipRDyr", "TipRDzr", "RootMxr", "RootMzr"}) {
    const double a = final_value(run.reference, ch), b = final_value(v5, ch), ours = final_value(run.ours, ch);
    const double margin = 1e-3 * std::max(std::abs(a), std::abs(b));
    INFO(ch << ": ours " << ours << ", r-test " << a << ", v5 " << b);
    CHECK(ours >= std::min(a, b) - margin);
    CHECK(ours <= std::max(a, b) + margin);
  }
}

TEST_CASE("BeamDyn static cantilever under gravity", "[verification][beamdyn]") {
  const BeamDynRun run = run_rtest("bd_static_cantilever_beam", 64);
  // A 10 m beam bent by its weight to a tip rotation of 88°: BeamDyn's one 5th-order element
  // does not resolve the 1 m bending boundary layer at the root, and its answer is 3.9 % short in
  // TipTDxr. Ours converges under refinement (16 → 256 segments: 9.4150 → 9.4176 m) and, made
  // inextensible, matches the exact elastica to 1e-5 (beam module test "heavy cantilever"). The
  // 5 % bound is BeamDyn's under-resolution, not ours.
  for (const char* ch : {"TipTDxr", "TipTDzr", "TipRDyr"}) {
    INFO(ch << ": ours " << final_value(run.ours, ch) << ", BeamDyn " << final_value(run.reference, ch));
    CHECK(std::abs(final_value(run.ours, ch) / final_value(run.reference, ch) - 1.0) < 0.05);
  }
}

TEST_CASE("BeamDyn pretwisted beam under a tip force", "[verification][beamdyn]") {
  const BeamDynRun run = run_rtest("bd_static_twisted_with_k1", 64);
  // Linear twist 0→90° couples the bending planes. Measured agreement 4e-4 of the deflection
  // magnitude (4.1 m); BeamDyn adds an extension–twist term we do not model, and we use 64
  // second-order volumes: 1e-3 bounds both.
  const double scale = 4.1;
  for (const char* ch : {"TipTDxr", "TipTDyr", "TipTDzr"}) {
    INFO(ch << ": ours " << final_value(run.ours, ch) << ", BeamDyn " << final_value(run.reference, ch));
    CHECK(std::abs(final_value(run.ours, ch) - final_value(run.reference, ch)) < 1e-3 * scale);
  }
  for (const char* ch : {"RootMxr", "RootMzr"}) {  // measured 3e-4 of |RootMxr| = 3.5e7 N·m
    CHECK(std::abs(final_value(run.ours, ch) - final_value(run.reference, ch)) < 1e-3 * 3.54e7);
  }
}

TEST_CASE("NREL 5MW blade hanging under gravity (BeamDyn Az00, 30 s)", "[verification][beamdyn]") {
  const std::string name = "bd_5MW_dynamic_gravity_Az00";
  const BeamDynRun run = run_rtest(name, 48);
  // BeamDyn's single 5th-order element is 1.2 % stiffer in flap (0.692 vs our converged 0.684 Hz,
  // unchanged from 24 to 96 segments), so the free response drifts in phase over 30 s: compare
  // level (mean) and amplitude (std) of the response. Measured ≤ 1.4 % except RootMyr std (2.5 %).
  for (const char* ch : {"TipTDxr", "TipTDyr", "RootMxr", "RootMyr"}) {
    const SignalComparison c = compare_signal(run, ch, 0.0);
    INFO(ch << ": mean " << c.mean_ours << " vs " << c.mean_reference << ", std " << c.std_ours << " vs " << c.std_reference);
    CHECK(std::abs(c.std_ours / c.std_reference - 1.0) < 0.03);
    if (std::string(ch) != "RootMyr")  // RootMyr's mean is ~0.5 % of its std: not a level to compare
      CHECK(std::abs(c.mean_ours / c.mean_reference - 1.0) < 0.03);
  }
}

TEST_CASE("NREL 5MW blade spinning at 12.1 rpm under gravity (seed Table 2.3)", "[verification][beamdyn]") {
  const auto dir = testing::shared_dir_or_skip() / "reference/openfast-runs/bd_5MW_rotating_gravity";
  const BeamDynRun run = run_beamdyn_reference(dir / "bd_driver.inp", dir / "bd_driver.out", 48,
                                               testing::scratch_dir("beamdyn_5MW_rotating") / "bd_5MW_rotating_gravity");
  // Seed Table 2.3 over the last 180 s of 300 s: RMS(MBBT − BeamDyn)/RMS(BeamDyn) was 1.23 %
  // edgewise (TipTDyr), 5.96 % flapwise (TipTDxr), 2.00 % axial (TipTDzr; its value is the
  // fluctuation about a 12 mm centrifugal stretch, so the std ratio is the comparable measure).
  // Issue 3: no worse than the seed.
  const SignalComparison edge = compare_signal(run, "TipTDyr", 120.0);
  const SignalComparison flap = compare_signal(run, "TipTDxr", 120.0);
  const SignalComparison axial = compare_signal(run, "TipTDzr", 120.0);
  INFO("edge " << edge.rms_difference_over_rms << ", flap " << flap.rms_difference_over_rms << ", axial "
               << axial.std_difference_over_std);
  CHECK(edge.rms_difference_over_rms < 0.0123);
  CHECK(flap.rms_difference_over_rms < 0.0596);
  CHECK(axial.std_difference_over_std < 0.0200);
  // Root moments likewise: the edgewise moment (gravity, 1P) as the edgewise tip deflection.
  CHECK(compare_signal(run, "RootMxr", 120.0).rms_difference_over_rms < 0.0123);
  CHECK(compare_signal(run, "RootMzr", 120.0).rms_difference_over_rms < 0.0200);  // pitching moment, measured 1.1 %
  // The flapwise root moment is a decayed free vibration of 0.1 % of the edgewise moment whose
  // phase drifts with the 1 % frequency offset above: compare its amplitude (measured 4 %).
  const SignalComparison flap_moment = compare_signal(run, "RootMyr", 120.0);
  CHECK(std::abs(flap_moment.std_ours / flap_moment.std_reference - 1.0) < 0.10);
}

TEST_CASE("NREL 5MW blade at 12.1 rpm: reusing the step matrix leaves the response unchanged", "[verification][beamdyn]") {
  const auto dir = testing::shared_dir_or_skip() / "reference/openfast-runs/bd_5MW_rotating_gravity";
  const auto scratch = testing::scratch_dir("beamdyn_5MW_matrix_reuse");
  const BeamDynRun reused = run_beamdyn_reference(dir / "bd_driver.inp", dir / "bd_driver.out", 48, scratch / "reused");
  const BeamDynRun rebuilt =
      run_beamdyn_reference(dir / "bd_driver.inp", dir / "bd_driver.out", 48, scratch / "rebuilt", std::nullopt, 1);
  const BeamDynRun pair{reused.ours, rebuilt.ours, 0.0, 0.0};
  // The default reuse (beam README, departure 7) against the seed's scheme, the step matrix rebuilt
  // every step: the residual is exact either way, so they differ only through the corrections.
  // Measured ≤ 6e-8 of the RMS over 120–300 s; the bound 1e-6 is four orders below the 1 %
  // agreement with BeamDyn checked above, so the reuse cannot move any Table 2.3 figure. The
  // flapwise root moment, a decayed free vibration of 0.1 % of the edgewise one, differs by 2e-6
  // of its own RMS (2e-9 of RootMxr's): bound 1e-5.
  for (const char* ch : {"TipTDxr", "TipTDyr", "RootMxr", "RootMyr"}) {
    const double d = compare_signal(pair, ch, 120.0).rms_difference_over_rms;
    INFO(ch << ": RMS(reused − rebuilt)/RMS " << d << "; wall " << reused.wall_s << " s vs " << rebuilt.wall_s << " s");
    CHECK(d < (std::string(ch) == "RootMyr" ? 1e-5 : 1e-6));
  }
}

TEST_CASE("NREL 5MW blade natural frequencies against the published values", "[verification][beamdyn]") {
  const BeamDynSetup setup = beamdyn_setup(io::read_beamdyn_driver(rtest("bd_5MW_dynamic_gravity_Az00") / "bd_driver.inp"));
  const beam::BeamModel model = beam::discretise(setup.definition, 48);
  const std::vector<double> f = beam::natural_frequencies_hz(model, beam::BeamInput{}, beam::make_state(model), 3);
  INFO("f = " << f[0] << ", " << f[1] << ", " << f[2] << " Hz");
  // PUBLISHED.md (NREL/TP-500-38060 Table 9-1), ADAMS column: 1st collective flap 0.7019, 1st
  // edgewise 1.0740, 2nd collective flap 1.9601 Hz — full-system values the isolated blade lies
  // close to; issue 3 asks for 3 %. ADAMS models the blade as a beam of many bodies, as we do;
  // the FAST column (ElastoDyn: two assumed flap shapes, a Rayleigh–Ritz upper bound) gives
  // 2.0205 Hz for the 2nd flap mode, 3.7 % above ours (printed by `fowtsim verify beam-5mw`).
  // Ours are converged (24 → 96 segments) and equal Euler–Bernoulli (0.692, 1.114, 1.992 Hz)
  // when twist and shear flexibility are removed.
  CHECK(std::abs(f[0] / 0.7019 - 1.0) < 0.03);
  CHECK(std::abs(f[1] / 1.0740 - 1.0) < 0.03);
  CHECK(std::abs(f[2] / 1.9601 - 1.0) < 0.03);
}
