// `fowtsim verify flexbody`: the Rayleigh–Ritz flexible bodies of seed paper 002 (modules/flexbody),
// the headline checks of its module tests through fowtsim/flexbody/verification.hpp (the same
// computations the tests run, with the same bounds and sources), and Kane's spin-up against the
// MBBT beam through verify/kane_spin_up.hpp (shared with driver/tests/kane_spin_up_tests.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "verify/kane_spin_up.hpp"
#include "verify/prebent_spin_up.hpp"
#include "verify/rr_blade_comparison.hpp"
#include "verify/verify_cases.hpp"
#include "verify/verify_modules.hpp"
#include "fowtsim/flexbody/two_bladed_turbine.hpp"
#include "fowtsim/flexbody/verification.hpp"

namespace fowtsim::driver {
namespace {

using namespace flexbody::verification;

VerificationRow below(const std::string& case_name, const std::string& metric, double value, double limit, const std::string& source) {
  return {case_name, metric, value, fmt::format("< {:.3g}", limit), source, value < limit};
}

// Sec. 5.1: the uniform clamped-free beam, its closed forms, top-mass modes and buckling loads.
void sec51_rows(std::FILE* out, const std::string& c, std::vector<VerificationRow>& rows) {
  // Top mass 3.5e5 kg under g = 9.81 (the module test's; centrifugal Ω 1.2 rad/s, r 3 m, not a row).
  const CosineBeam b = cosine_beam_closed_forms(3.5e5, 9.81, 1.2, 3.0);
  fmt::print(out, "Sec. 5.1, u = 1 − cos(πx/2L), L 100 m, EI 2e12 N·m², m 9e3 kg/m, M_t 3.5e5 kg:\n");
  fmt::print(out, "  M_q {:.10e} [{:.10e}], K_q {:.10e} [{:.10e}] (closed forms in brackets)\n", b.Mq.value, b.Mq.exact,
             b.Kq.value, b.Kq.exact);
  fmt::print(out, "  K_MT/K_q {:.10f} [{:.10f}], K_SW/K_q {:.10f} [{:.10f}]\n", b.top_mass_ratio.value, b.top_mass_ratio.exact,
             b.self_weight_ratio.value, b.self_weight_ratio.exact);
  // Quadrature error < 1e-14 here (64 Gauss points on a smooth integrand): rounding, 1e-12.
  const std::string closed = "seed 002 Sec. 5.1 closed forms";
  rows.push_back(below(c, "Sec. 5.1 M_q: |rel. diff|", std::abs(b.Mq.relative_error()), 1e-12, closed));
  rows.push_back(below(c, "Sec. 5.1 K_q: |rel. diff|", std::abs(b.Kq.relative_error()), 1e-12, closed));
  rows.push_back(below(c, "Sec. 5.1 K_MT/K_q = −M_t g/P_cr: |rel. diff|", std::abs(b.top_mass_ratio.relative_error()), 1e-12, closed));
  rows.push_back(below(c, "Sec. 5.1 K_SW/K_q: |rel. diff|", std::abs(b.self_weight_ratio.relative_error()), 1e-12, closed));

  // M_t = M/2: the eq. 32 top-mass modes are the eigenfunctions, so RR on them is exact;
  // 1e-10 covers quadrature (1e-13) and eigen-solver rounding.
  double worst = 0.0;
  fmt::print(out, "  eq. 32 modes with M_t = M/2, ω [rad/s] RR [eq. 32]:");
  for (const Checked& w : top_mass_mode_frequencies(0.5, 4)) {
    fmt::print(out, " {:.9f} [{:.9f}]", w.value, w.exact);
    worst = std::max(worst, std::abs(w.relative_error()));
  }
  fmt::print(out, "\n");
  rows.push_back(below(c, "eq. 32 top-mass modes 1–4, M_t = M/2: worst |rel. diff| of ω", worst, 1e-10, "seed 002 eq. 32"));

  // x̃²..x̃⁶: Euler's load is approached from above (RR); measured +8.6e-9, bound ~3×.
  const Buckling k = column_buckling(5);
  fmt::print(out, "  buckling, x̃²..x̃⁶: tip load {:.8e} N [π²EI/(4L²) {:.8e}], Greenhill (mgL)_cr L²/EI {:.6f} [7.8373]\n",
             k.euler.value, k.euler.exact, k.greenhill);
  rows.push_back(below(c, "Euler tip-load buckling vs π²EI/(4L²): rel. diff", k.euler.relative_error(), 3e-8, "Euler; seed 002 Sec. 5.1"));
  rows.push_back(below(c, "Euler buckling ≥ exact (RR upper bound): −rel. diff", -k.euler.relative_error(), 1e-12, "Rayleigh–Ritz bound"));
  // Tolerance: the 5 digits of the constant.
  rows.push_back(below(c, "Greenhill self-weight buckling vs 7.8373 EI/L²: |rel. diff|", std::abs(k.greenhill / 7.8373 - 1.0), 5e-5,
                       "Timoshenko & Gere §2.13"));
}

// welib yams/tests/test_flexibility.py test_GMGKBeam: diagonals of M_q, K_q and ∫ m u_j with its
// station-trapezoid rule on 30 stations.
void welib_rows(std::FILE* out, const std::string& c, std::vector<VerificationRow>& rows) {
  const UniformBeamMatrices b = welib_uniform_beam(flexbody::QuadratureRule::Kind::StationTrapezoid);
  const double M[3] = {7508.18374, 7528.42330, 7546.66429}, K[3] = {286478.07306, 11281454.27909, 88662737.01300},
               first[3] = {11748.96793, -6494.82063, 3839.68233};
  double worst[3] = {0.0, 0.0, 0.0};
  for (int j = 0; j < 3; ++j) {
    worst[0] = std::max(worst[0], std::abs(b.M(j, j) / M[j] - 1.0));
    worst[1] = std::max(worst[1], std::abs(b.K(j, j) / K[j] - 1.0));
    worst[2] = std::max(worst[2], std::abs(b.first_moment(j) / first[j] - 1.0));
  }
  fmt::print(out, "welib uniform beam (L 60 m, 3 modes, trapezoid on 30 stations): M_jj {:.5f} {:.5f} {:.5f}; K_jj {:.2f} {:.2f} {:.2f}; "
                  "∫m u_j {:.5f} {:.5f} {:.5f}\n",
             b.M(0, 0), b.M(1, 1), b.M(2, 2), b.K(0, 0), b.K(1, 1), b.K(2, 2), b.first_moment(0), b.first_moment(1), b.first_moment(2));
  // welib's own rtol, 1e-5 (its references carry 9–11 digits).
  const std::string welib = "welib test_GMGKBeam (rtol 1e-5)";
  rows.push_back(below(c, "welib beam M_jj (7508.18374 …): worst |rel. diff|", worst[0], 1e-5, welib));
  rows.push_back(below(c, "welib beam K_jj (286478.07 …): worst |rel. diff|", worst[1], 1e-5, welib));
  rows.push_back(below(c, "welib beam ∫m u_j (11748.97 …): worst |rel. diff|", worst[2], 1e-5, welib));
}

// Sec. 5.5, Table 1: mixed FEM–RR, Guyan and Craig–Bampton models, δf_2 and δf_4 vs eq. 32.
void table1_rows(std::FILE* out, const std::string& c, std::vector<VerificationRow>& rows) {
  fmt::print(out, "Table 1 (Sec. 5.5), errors vs eq. 32 in %: ours [seed]\n");
  for (const auto& [mixed, seed] : seed_table1()) {
    const MixedErrors e = mixed_case_errors(mixed);
    const double ours[4] = {100 * e.f[0], 100 * e.f[1], 100 * e.u[0], 100 * e.u[1]};
    fmt::print(out, "  {:<18} δf2 {:7.3f} [{:6.2f}]  δf4 {:7.3f} [{:6.2f}]  δu2 {:6.3f} [{:5.2f}]  δu4 {:6.3f} [{:5.2f}]\n", mixed.name,
               ours[0], seed[0], ours[1], seed[1], ours[2], seed[2], ours[3], seed[3]);
    // Within 0.1 percentage point + 8 % of the seed's value: 0.1 covers its 2-decimal rounding and
    // its ±0.05 offsets (negative errors no conforming model gives); 8 % the largest relative gap
    // measured, 6.7 % on GY2-RR4c δf_4 (its frequencies are a little lower throughout; not traced).
    for (int k = 0; k < 2; ++k)
      rows.push_back(below(c, fmt::format("Table 1 {} δf{}: {:.3f} % vs {:.2f} %, |diff| [%]", mixed.name, 2 * k + 2, ours[k], seed[k]),
                           std::abs(ours[k] - seed[k]), 0.1 + 0.08 * std::abs(seed[k]), "seed 002 Table 1"));
    // Every model is conforming: its frequencies bound eq. 32's from above; 1e-9 is eigen-solver rounding.
    rows.push_back(below(c, fmt::format("Table 1 {}: ω_2, ω_4 ≥ exact (RR bound): −min(δf)", mixed.name), -std::min(e.f[0], e.f[1]),
                         1e-9, "Rayleigh–Ritz bound"));
  }
}

// Sec. 6 two-bladed turbine: eq. 36's M_q and K_q at q = [1 1 1 1], to half a unit of the print.
void sec6_rows(std::FILE* out, const std::string& c, std::vector<VerificationRow>& rows) {
  const flexbody::TurbineMatrices r = flexbody::two_bladed_turbine_matrices(flexbody::TwoBladedTurbine{}, Eigen::Vector4d::Ones());
  const struct {
    const char* name;
    double value, printed;
  } entries[] = {{"M_q11", r.Mq(0, 0), 7.86e5}, {"M_q22", r.Mq(1, 1), 7.23e7}, {"M_q33", r.Mq(2, 2), 7.50e3},
                 {"M_q44", r.Mq(3, 3), 7.50e3}, {"M_q14", r.Mq(0, 3), 1.58e4}, {"K_q11", r.Kq(0, 0), 6.01e6},
                 {"K_q33", r.Kq(2, 2), 2.86e5}};
  fmt::print(out, "Sec. 6 two-bladed turbine at q = [1 1 1 1], ours [seed's print]:");
  for (const auto& e : entries) fmt::print(out, " {} {:.5e} [{:.2e}]", e.name, e.value, e.printed);
  fmt::print(out, "\n  Misprints (not rows; modules/flexbody README): M_q13 printed 7.71e3, ours {:.5e} (7.70497e3 on the author's "
                  "stations: a double rounding); K_q44 printed 2.86e6, ours {:.5e} = K_q33 (identical blades)\n",
             r.Mq(0, 2), r.Kq(3, 3));
  // The seed prints three significant digits: half a unit of the last one is what its rounding allows.
  for (const auto& e : entries)
    rows.push_back(below(c, fmt::format("Sec. 6 {} {:.5e} vs {:.2e}: |diff| / half unit of last digit", e.name, e.value, e.printed),
                         printed_digit_error(e.value, e.printed, 3), 1.0, "seed 002 eq. 36"));
}

// Sec. 5.3: torsion of the tube under a near-resonant tip moment, RK4 vs the analytic transient.
void torsion_rows(std::FILE* out, const std::string& c, std::vector<VerificationRow>& rows) {
  // RK4 at 0.5 ms (4th order measured), sampled every 5 ms over 5 s (28 periods).
  const TorsionTransient t = torsion_transient(TorsionTube{}, 5.0, 5e-3, 5e-4);
  fmt::print(out, "Sec. 5.3 torsion (tube L 100 m, M₀ 50 GN·m, Ω/ω₁ 1.0002, 0–5 s): 1 shape vs analytic {:.2e} rad; 4 shapes vs Σ "
                  "modal {:.2e} rad; vs the seed's 1-DOF max {:.3f} rad (envelope of shapes 2–4 {:.3f} rad), RMS {:.3f} rad; peak {:.2f} rad\n",
             t.one_shape_error, t.modal_error, t.one_dof_difference, t.omitted_envelope, t.one_dof_rms, t.peak);
  // Measured 2.2e-6 rad (RK4 error): 10× with margin.
  const std::string analytic = "one-DOF transient (derived; seed 002 Sec. 5.3)";
  rows.push_back(below(c, "Sec. 5.3 torsion, 1 shape vs analytic transient: max |diff| [rad]", t.one_shape_error, 2e-5, analytic));
  rows.push_back(below(c, "Sec. 5.3 torsion, 4 shapes vs Σ modal transients: max |diff| [rad]", t.modal_error, 2e-5, analytic));
  // The seed's "perfect fit" of the 1-DOF formula: the difference is the omitted shapes' quasi-static
  // response, bounded by their envelope Σ_{j≥2}(A_j + H₀_j) (derived, not fitted).
  rows.push_back(below(c, "Sec. 5.3 torsion, 4 shapes vs 1-DOF: max |diff| / omitted envelope", t.one_dof_difference / t.omitted_envelope,
                       1.0, "envelope of shapes 2–4 (derived)"));
  rows.push_back(below(c, "Sec. 5.3 torsion, 4 shapes vs 1-DOF: RMS diff / peak", t.one_dof_rms / t.peak, 0.01, "seed 002 Sec. 5.3 (\"perfect fit\")"));
  // Measured 89.81 (H₀ = 90.2); ±0.5: the 5 ms sampling misses a crest by up to 0.35 rad.
  rows.push_back(below(c, "Sec. 5.3 torsion, peak tip twist vs 89.8 rad: |diff| [rad]", std::abs(t.peak - 89.8), 0.5, "module test (measured)"));
}

// Sec. 5.2 Kane's spin-up: RR tip vs the MBBT beam (modules/beam), 0–20 s.
void kane_rows(std::FILE* out, const std::string& c, std::vector<VerificationRow>& rows) {
  const KaneSpinUp h = kane_spin_up_histories();
  const double e1 = rms_over_max(h.rr1, h.mbbt), e3 = rms_over_max(h.rr3, h.mbbt);
  const double same = max_abs_difference(h.rr3, h.beam_rr3) / max_abs(h.beam_rr3);
  fmt::print(out, "Sec. 5.2 Kane's spin-up (L 10 m, Ω_s 6 rad/s, 0–20 s): max |tip| MBBT {:.4f} m, RR-1 {:.4f} m, RR-3 {:.4f} m; "
                  "RMS diff / max: 1 mode {:.3f} %, 3 modes {:.3f} %; RR-3 vs modules/beam's RR {:.1e} of max\n\n",
             max_abs(h.mbbt), max_abs(h.rr1), max_abs(h.rr3), 100 * e1, 100 * e3, same);
  // The seed's figures against its nonlinear lumped-mass code, 0.5 % (1 shape) and 0.3 % (3): the
  // MBBT beam is likewise geometrically exact; the RR drops slope² ≈ 0.3 % terms. Measured 0.40 %, 0.052 %.
  rows.push_back(below(c, "Sec. 5.2 Kane spin-up, RR 1 mode vs MBBT: RMS diff / max tip", e1, 0.005, "seed 002 Sec. 5.2 (0.5 %)"));
  rows.push_back(below(c, "Sec. 5.2 Kane spin-up, RR 3 modes vs MBBT: RMS diff / max tip", e3, 0.003, "seed 002 Sec. 5.2 (0.3 %)"));
  // Same model coded separately (Simpson vs Gauss, same RK4 steps): quadrature and rounding, 1e-10.
  rows.push_back(below(c, "Sec. 5.2 Kane spin-up, RR 3 modes vs modules/beam's RR: max diff / max tip", same, 1e-10,
                       "independent implementation"));
}

// Sec. 5.4 pre-bent beam spun up: coupled edge–flap–torsion RR vs the MBBT beam on the curved
// line, 0–30 s; bounds and reasons as in driver/tests/prebent_spin_up_tests.cpp.
void prebent_rows(std::FILE* out, const std::string& c, std::vector<VerificationRow>& rows) {
  const PrebentComparison p = compare(prebent_spin_up_histories());
  fmt::print(out, "Sec. 5.4 pre-bent spin-up (z0(L) −0.5 m, 0–30 s): edge RMS diff / max {:.2f} %; flap z(L) at 30 s MBBT {:.4f} m, "
                  "RR {:.4f} m (seed ≈ −0.13); tip twist min MBBT {:.4f} rad, RR {:.4f} rad (seed: negative, RR over-predicts)\n\n",
             100 * p.edge_rms_over_max, p.flap_final_mbbt, p.flap_final_rr, p.torsion_min_mbbt, p.torsion_min_rr);
  rows.push_back(below(c, "Sec. 5.4 pre-bent spin-up, RR vs MBBT edge tip: RMS diff / max", p.edge_rms_over_max, 0.05, "measured 0.45 %, 10×"));
  rows.push_back(below(c, "Sec. 5.4 pre-bent spin-up, MBBT flap z(L) at 30 s vs −0.13 m: |diff| [m]", std::abs(p.flap_final_mbbt + 0.13), 0.01,
                       "seed 002 Sec. 5.4 (\"about −0.13 m\")"));
  rows.push_back(below(c, "Sec. 5.4 pre-bent spin-up, RR flap z(L) at 30 s vs −0.13 m: |diff| [m]", std::abs(p.flap_final_rr + 0.13), 0.01,
                       "seed 002 Sec. 5.4 (\"about −0.13 m\")"));
  rows.push_back(below(c, "Sec. 5.4 pre-bent spin-up, RR vs MBBT flap tip: max diff [m]", p.flap_max_difference, 0.025, "measured 2.5e-3 m, 10×"));
  rows.push_back(below(c, "Sec. 5.4 pre-bent spin-up, MBBT min tip twist (negative) [rad]", p.torsion_min_mbbt, -0.05, "seed 002 Sec. 5.4 (negative)"));
  rows.push_back(below(c, "Sec. 5.4 pre-bent spin-up, RR min tip twist (negative) [rad]", p.torsion_min_rr, -0.05, "seed 002 Sec. 5.4 (negative)"));
  rows.push_back(below(c, "Sec. 5.4 pre-bent spin-up, RR / MBBT peak twist − 1", std::abs(p.torsion_min_rr / p.torsion_min_mbbt - 1.0), 0.3,
                       "measured 3.3 % under, 10×"));
  rows.push_back(below(c, "Sec. 5.4 pre-bent spin-up, RR vs MBBT twist: RMS diff / max", p.torsion_rms_over_max, 0.4, "measured 4.2 %, 10×"));
}


// ElastoDyn's Rayleigh–Ritz blade (flexbody rr_blade.hpp): its mass moments on ElastoDyn's own rule
// against ElastoDyn's summary file, its frequencies against our MBBT beam of the same blade (the
// bounds and their reasons as in driver/tests/rr_blade_mbbt_tests.cpp).
void rr_blade_rows(std::FILE* out, const std::string& c, std::vector<VerificationRow>& rows) {
  const std::filesystem::path beamdyn =
      shared_dir() / "reference/r-test/modules/beamdyn/bd_5MW_dynamic_gravity_Az00/bd_driver.inp";
  if (!std::filesystem::exists(beamdyn)) {
    fmt::print(out, "RR blade against MBBT: no BeamDyn blade at {} (rows skipped)\n", beamdyn.string());
    return;
  }
  const RrBladeComparison r = rr_blade_comparison(source_input("nrel5mw/blade_elastodyn.yaml"), beamdyn);
  fmt::print(out, "NREL 5MW blade, ElastoDyn's RR body: mass {:.4f} kg, first moment {:.4f} kg·m, second {:.4f} kg·m² "
                  "(ElastoDyn's 17 nodes; its summary: 17536.614, 362132.653, 11752352.265)\n",
             r.elastodyn_rule.mass, r.elastodyn_rule.first_moment, r.elastodyn_rule.second_moment);
  fmt::print(out, "  frequencies at rest (flap 1, edge 1, flap 2): RR {:.4f} {:.4f} {:.4f} Hz, MBBT {:.4f} {:.4f} {:.4f} Hz\n",
             r.rr_rest_hz(0), r.rr_rest_hz(1), r.rr_rest_hz(2), r.mbbt_rest_hz[0], r.mbbt_rest_hz[1], r.mbbt_rest_hz[2]);
  fmt::print(out, "  at 12.1 rpm: RR {:.4f} {:.4f} {:.4f} Hz, MBBT {:.4f} {:.4f} {:.4f} Hz\n", r.rr_spinning_hz(0),
             r.rr_spinning_hz(1), r.rr_spinning_hz(2), r.mbbt_spinning_hz[0], r.mbbt_spinning_hz[1], r.mbbt_spinning_hz[2]);
  // Half a unit of the summary's last printed digit (measured 1.4e-4 to 3e-4: its rounding).
  const std::string summary = "ElastoDyn summary 5MW_OC3Spar_DLL_WTurb_WavesIrr.ED.sum";
  rows.push_back(below(c, "RR blade mass (17 nodes) vs 17536.614 kg: |diff| [kg]", std::abs(r.elastodyn_rule.mass - 17536.614), 5e-4, summary));
  rows.push_back(below(c, "RR blade first mass moment vs 362132.653 kg·m: |diff|",
                       std::abs(r.elastodyn_rule.first_moment - 362132.653), 5e-4, summary));
  rows.push_back(below(c, "RR blade second mass moment vs 11752352.265 kg·m²: |diff|",
                       std::abs(r.elastodyn_rule.second_moment - 11752352.265), 5e-4, summary));
  // Two beam models of one blade (ElastoDyn's EI table and fixed shapes against BeamDyn's 6×6
  // sections): measured −0.42, +1.17, +2.41 %; bounds 2, 3, 5 %.
  const std::string model = "our MBBT beam of the BeamDyn blade (model difference)";
  const double bounds[] = {0.02, 0.03, 0.05};
  const char* names[] = {"flap 1", "edge 1", "flap 2"};
  for (int k = 0; k < 3; ++k)
    rows.push_back(below(c, fmt::format("RR blade {} at rest vs MBBT: |rel. diff|", names[k]),
                         std::abs(r.rr_rest_hz(k) / r.mbbt_rest_hz[k] - 1.0), bounds[k], model));
  // The centrifugal rise of flap 1: RR +7.49 %, MBBT +7.37 %; their ratio within 1 % (~8× measured).
  rows.push_back(below(c, "RR blade flap-1 rise at 12.1 rpm vs MBBT's: |ratio − 1|",
                       std::abs((r.rr_spinning_hz(0) / r.rr_rest_hz(0)) / (r.mbbt_spinning_hz[0] / r.mbbt_rest_hz[0]) - 1.0), 0.01,
                       "our MBBT beam, stress-stiffened about its spinning equilibrium"));
}

}  // namespace

std::vector<VerificationRow> verify_flexbody(std::FILE* out) {
  std::vector<VerificationRow> rows;
  const std::string c = "flexbody";
  sec51_rows(out, c, rows);
  welib_rows(out, c, rows);
  table1_rows(out, c, rows);
  sec6_rows(out, c, rows);
  torsion_rows(out, c, rows);
  kane_rows(out, c, rows);
  prebent_rows(out, c, rows);
  rr_blade_rows(out, c, rows);
  return rows;
}

}  // namespace fowtsim::driver
