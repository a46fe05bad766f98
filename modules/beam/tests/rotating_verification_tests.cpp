// Beams in a rotating floating frame (issue 3): the rotating straight beam of seed 000 §2.5.3
// (Coriolis coupling) and Kane's spin-up beam of seed 002 §5.2 (centrifugal stiffening), run with
// the default dynamic stepper (generalized-α, ρ∞ = 0), inputs sampled at input_time_fraction().
//
// Axes: both beams lie along f's x with the seeds' axes (rotating_benchmarks.hpp), so every
// component below is in the seeds' (x, y, z).
#include <algorithm>
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/beam/beam_outputs.hpp"
#include "fowtsim/beam/rotating_benchmarks.hpp"
#include "fowtsim/beam/solvers.hpp"

using namespace fowtsim;
using namespace fowtsim::beam;

namespace {

// ---- seed 000 §2.5.3 --------------------------------------------------------------------------

constexpr double kRotatingEnd = 2.0;      // simulated span [s]: ~8 load periods
constexpr double kRotatingSample = 0.005;  // common output grid of all time steps [s]

struct RotatingRun {
  Vec3 static_tip = Vec3::Zero();  // tip displacement of the static start [m]
  std::vector<Vec3> tip;           // tip displacement at t = k·kRotatingSample, in f [m]
  double max_abs(int axis) const {
    double m = 0.0;
    for (const Vec3& v : tip) m = std::max(m, std::abs(v[axis]));
    return m;
  }
};

// Static equilibrium under the tip force and the steady rotation (centrifugal loads come from the
// frame kinematics), then the distributed load W sin(ωt) from t = 0 — the seed's "static tip force
// plus a dynamic load". Starting from this equilibrium avoids the free vibration that applying
// 5000 kN suddenly would excite.
RotatingRun run_rotating(int segments, double dt, double spin) {
  const BeamModel model = discretise(benchmarks::rotating_steel_beam(), segments);
  BeamState state = make_state(model);
  StaticOptions static_options;
  static_options.load_steps = 10;  // the tip force bends the beam by ~25 % of its length
  solve_static(model, benchmarks::rotating_beam_input(model, 0.0, spin), state, static_options);
  RotatingRun run;
  run.static_tip = beam_outputs(model, state).tip_displacement_m;
  run.tip.push_back(run.static_tip);
  DynamicStepper stepper(model, DynamicOptions{});
  const long per_sample = std::lround(kRotatingSample / dt);
  const long steps = std::lround(kRotatingEnd / dt);
  for (long k = 0; k < steps; ++k) {
    stepper.step(benchmarks::rotating_beam_input(model, (k + stepper.input_time_fraction()) * dt, spin), dt, state);
    if ((k + 1) % per_sample == 0) run.tip.push_back(beam_outputs(model, state).tip_displacement_m);
  }
  return run;
}

// Largest difference of one tip component between two runs on the common output grid.
double max_difference(const RotatingRun& a, const RotatingRun& b, int axis) {
  double m = 0.0;
  for (std::size_t k = 0; k < a.tip.size(); ++k) m = std::max(m, std::abs(a.tip[k][axis] - b.tip[k][axis]));
  return m;
}

// ---- seed 002 §5.2 ----------------------------------------------------------------------------

constexpr double kKaneEnd = 20.0;     // 15 s spin-up + 5 s at 6 rad/s [s]
constexpr double kKaneSample = 0.02;  // common output grid [s]

// In-plane tip deflection (along f's y, in the rotating frame) at t = k·kKaneSample, from rest.
std::vector<double> run_kane(int segments, double dt) {
  const BeamModel model = discretise(benchmarks::kane_beam(), segments);
  BeamState state = make_state(model);
  DynamicStepper stepper(model, DynamicOptions{});
  const long per_sample = std::lround(kKaneSample / dt);
  const long steps = std::lround(kKaneEnd / dt);
  std::vector<double> tip{0.0};
  BeamInput input;
  for (long k = 0; k < steps; ++k) {
    input.frame = benchmarks::kane_frame((k + stepper.input_time_fraction()) * dt);
    stepper.step(input, dt, state);
    if ((k + 1) % per_sample == 0) tip.push_back(beam_outputs(model, state).tip_displacement_m.y());
  }
  return tip;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) m = std::max(m, std::abs(a[k] - b[k]));
  return m;
}

}  // namespace

TEST_CASE("rotating straight beam (seed 000 §2.5.3) responds out of plane through Coriolis",
          "[verification][beam]") {
  const RotatingRun run = run_rotating(30, 0.005, benchmarks::kRotatingBeamSpin);
  const double y_max = run.max_abs(1), z_max = run.max_abs(2);
  INFO("static tip " << run.static_tip.transpose() << "; over 0–2 s max |x| " << run.max_abs(0)
                     << ", max |y| " << y_max << ", max |z| " << z_max << ", z/y " << z_max / y_max);
  // The centrifugal field Ω²(x, 0, z) and the loads have no z component on the z = 0 plane, and the
  // section is symmetric: the static start is exactly planar (round-off level).
  CHECK(std::abs(run.static_tip.z()) < 1e-12 * std::abs(run.static_tip.y()));
  // Physical size of the Coriolis response: flapwise (y) vibration shortens the beam, the axial
  // velocity ẋ (tip amplitude ≈ 0.18 m × 26 rad/s ≈ 5 m/s, span mean ≈ ¼ of it) meets the Coriolis
  // force 2 m Ω ẋ ≈ 2·981·10·1.2 ≈ 2.4e4 N/m along z, at ≈ 26 rad/s, above the in-plane (z) first
  // mode ω_z ≈ √(12.8² + 0.193·10²) ≈ 13.5 rad/s: static deflection q L⁴/(8 EI₁) ≈ 0.23 m times
  // |1/(1 − (26/13.5)²)| ≈ 0.37 gives ≈ 0.09 m, plus a start transient of the same order, i.e.
  // 0.1–0.2 m ≈ 3–6 % of |y| ≈ 3.1 m (measured 0.18 m, 5.7 %). The seed's Fig. 2.8 is not in the
  // extracted text; its description ("expected Coriolis effect ... in the z-direction") asks for
  // exactly this response. Bounds: the estimate's range widened by ~1.5–2.5× for its crudeness.
  CHECK(z_max > 0.02 * y_max);
  CHECK(z_max < 0.15 * y_max);
}

TEST_CASE("rotating straight beam (seed 000 §2.5.3) converges in time step and elements",
          "[verification][beam]") {
  const double spin = benchmarks::kRotatingBeamSpin;
  const RotatingRun dt1 = run_rotating(30, 0.005, spin), dt2 = run_rotating(30, 0.0025, spin),
                    dt4 = run_rotating(30, 0.00125, spin);
  const double z_max = dt4.max_abs(2);
  const double dy1 = max_difference(dt1, dt2, 1), dy2 = max_difference(dt2, dt4, 1);
  const double dz1 = max_difference(dt1, dt2, 2), dz2 = max_difference(dt2, dt4, 2);
  INFO("max |Δy| (0.005 vs 0.0025) " << dy1 << ", (0.0025 vs 0.00125) " << dy2 << ", ratio "
                                     << dy1 / dy2 << "; max |Δz| " << dz1 << ", " << dz2
                                     << ", ratio " << dz1 / dz2 << "; max |z| at 0.005 / 0.00125 "
                                     << dt1.max_abs(2) << " / " << z_max);
  // Second order in Δt (± 0.2, as the spatial order of the roll-up): halving Δt shrinks the
  // history differences by ≥ 2^1.8. Measured 3.68 (y) and 3.76 (z).
  CHECK(dy1 / dy2 > 3.48);
  CHECK(dz1 / dz2 > 3.48);
  // The Coriolis response is resolved, not a discretisation artefact: the finest pair differs by
  // less than 10 % of its amplitude anywhere in the 2 s history (measured 4 %), and its peak moves
  // by less than 5 % from the seed's Δt = 0.005 s to Δt/4 (measured 2.4 %).
  CHECK(dz2 < 0.1 * z_max);
  CHECK(std::abs(dt1.max_abs(2) - z_max) < 0.05 * z_max);

  const RotatingRun e15 = run_rotating(15, 0.005, spin), e60 = run_rotating(60, 0.005, spin);
  const double ey1 = max_difference(e15, dt1, 1), ey2 = max_difference(dt1, e60, 1);
  const double ez1 = max_difference(e15, dt1, 2), ez2 = max_difference(dt1, e60, 2);
  INFO("elements: max |Δy| (15 vs 30) " << ey1 << ", (30 vs 60) " << ey2 << ", ratio " << ey1 / ey2
                                        << "; max |Δz| " << ez1 << ", " << ez2 << ", ratio "
                                        << ez1 / ez2);
  // Second-order spatial accuracy (issue 3, as the roll-up: order 2 ± 0.2 → ratio ≥ 2^1.8 = 3.48).
  CHECK(ey1 / ey2 > 3.48);
  CHECK(ez1 / ez2 > 3.48);
  // The seed's 30 elements are converged: 30 vs 60 differ by < 1 % of the response (measured
  // 0.06 % of |y| and 0.25 % of |z|).
  CHECK(ey2 < 0.01 * dt1.max_abs(1));
  CHECK(ez2 < 0.01 * dt1.max_abs(2));
}

TEST_CASE("non-rotating straight beam (seed 000 §2.5.3, Ω = 0) stays in its plane",
          "[verification][beam]") {
  const RotatingRun run = run_rotating(30, 0.005, 0.0);
  INFO("max |y| " << run.max_abs(1) << ", max |z| " << run.max_abs(2));
  // Without rotation nothing couples the y-z planes (symmetric section, loads along y): the
  // out-of-plane response must vanish to round-off (issue 3: below 1e-9 relative).
  CHECK(run.max_abs(2) < 1e-9 * run.max_abs(1));
}

TEST_CASE("Kane's spin-up beam (seed 002 §5.2): centrifugal stiffening bounds the tip",
          "[verification][beam]") {
  const std::vector<double> beam = run_kane(30, 0.005);
  // Seed 002's corrected Rayleigh–Ritz model with 6 clamped-free modes (3 vs 6 modes differ by
  // 1.4e-4 m, so the truncation is negligible here), and the same model without the geometric
  // stiffness, which the seed reports as diverging.
  const std::vector<double> rr = benchmarks::kane_rayleigh_ritz_tip(kKaneEnd, kKaneSample, 6);
  const std::vector<double> linear =
      benchmarks::kane_rayleigh_ritz_tip(kKaneEnd, kKaneSample, 6, false);
  REQUIRE(beam.size() == rr.size());

  const auto beam_min = std::min_element(beam.begin(), beam.end());
  const auto rr_min = std::min_element(rr.begin(), rr.end());
  const double t_beam_min = kKaneSample * (beam_min - beam.begin());
  const double t_rr_min = kKaneSample * (rr_min - rr.begin());
  double sq_err = 0.0, sq_ref = 0.0, beam_max = 0.0, late_max = 0.0;
  for (std::size_t k = 0; k < beam.size(); ++k) {
    sq_err += (beam[k] - rr[k]) * (beam[k] - rr[k]);
    sq_ref += rr[k] * rr[k];
    beam_max = std::max(beam_max, std::abs(beam[k]));
    if (k * kKaneSample >= benchmarks::kKaneSpinUpTime) late_max = std::max(late_max, std::abs(beam[k]));
  }
  const double rel_rms = std::sqrt(sq_err / sq_ref);
  INFO("dip: beam " << *beam_min << " m at " << t_beam_min << " s, Rayleigh–Ritz " << *rr_min
                    << " m at " << t_rr_min << " s; relative RMS difference " << rel_rms
                    << "; max |tip| after 15 s " << late_max << " m; uncorrected linear model at 20 s "
                    << linear.back() << " m");

  // Seed 002 finds its corrected Rayleigh–Ritz model within 0.3–0.5 % relative RMS of a
  // geometrically nonlinear lumped-mass code; ours is a third geometrically nonlinear model, so
  // the same 0.5 % (measured 0.12 %; the RR drops terms of order slope² ≈ 0.08² ≈ 0.6 %).
  CHECK(rel_rms < 0.005);
  // The characteristic dip while the hub accelerates (the beam lags, −y): depth within the same
  // 0.5 % (measured 0.12 %), time within 0.1 s (5 output samples; measured equal).
  CHECK(std::abs(*beam_min - *rr_min) < 0.005 * std::abs(*rr_min));
  CHECK(std::abs(t_beam_min - t_rr_min) < 0.1);
  CHECK(*beam_min < -0.5);  // a dip of ~0.57 m (5.7 % of L), not a small-deflection artefact
  // After the spin-up (θ̈ → 0 smoothly) the tip returns to ~0: only a residual oscillation below
  // 2 % of the dip remains (no damping; measured 0.64 %, RR 0.6 %).
  CHECK(late_max < 0.02 * std::abs(*beam_min));
  // What a linear model without geometric stiffening gives: once θ̇ exceeds the first bending
  // frequency (3.8 rad/s) the in-plane centrifugal softening −m θ̇² v wins and the tip diverges
  // (seed 002: "the absence of correction lead to a diverging tip motion"). Ours stays bounded by
  // the dip; the uncorrected model is more than 100× beyond it by 20 s (measured ~1e21 m).
  CHECK(std::abs(linear.back()) > 100.0 * beam_max);
}

TEST_CASE("Kane's spin-up beam (seed 002 §5.2) converges in time step and elements",
          "[verification][beam]") {
  const std::vector<double> dt1 = run_kane(30, 0.02), dt2 = run_kane(30, 0.01), dt4 = run_kane(30, 0.005);
  const double d1 = max_difference(dt1, dt2), d2 = max_difference(dt2, dt4);
  const double dip = std::abs(*std::min_element(dt4.begin(), dt4.end()));
  INFO("max |Δtip| (0.02 vs 0.01) " << d1 << ", (0.01 vs 0.005) " << d2 << ", ratio " << d1 / d2
                                    << ", dip " << dip);
  // Second order in Δt (± 0.2): ratio ≥ 2^1.8. Measured 3.97.
  CHECK(d1 / d2 > 3.48);
  // Δt = 0.01 s is converged to < 0.2 % of the dip anywhere in 20 s (measured 0.03 %).
  CHECK(d2 < 0.002 * dip);

  const std::vector<double> e15 = run_kane(15, 0.01), e60 = run_kane(60, 0.01);
  const double e1 = max_difference(e15, dt2), e2 = max_difference(dt2, e60);
  INFO("elements: max |Δtip| (15 vs 30) " << e1 << ", (30 vs 60) " << e2 << ", ratio " << e1 / e2);
  // Second-order spatial accuracy (order 2 ± 0.2 as for the roll-up → ratio ≥ 2^1.8 = 3.48;
  // measured 3.9), and 30 elements within 0.1 % of the dip of 60 (measured 0.03 %).
  CHECK(e1 / e2 > 3.48);
  CHECK(e2 < 0.001 * dip);
}
