// Kane's spin-up beam (seed 002 Sec. 5.2) across two modules: the Rayleigh–Ritz equations of
// modules/flexbody (spinning_beam.hpp, eq. 32 modes, geometric stiffening of eq. 26) against the
// MBBT finite-volume beam of modules/beam, both spun up by the same prescribed hub motion. The
// MBBT beam is clamped at the origin of a floating frame that rotates about z with Ω(t), α(t)
// (FrameKinematics: the frame's inertial loads, as modules/beam's own Kane test drives it) and is
// geometrically exact, so it plays the role of the seed's nonlinear lumped-mass reference.
#include <algorithm>
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/beam/beam_outputs.hpp"
#include "fowtsim/beam/rotating_benchmarks.hpp"
#include "fowtsim/beam/solvers.hpp"
#include "fowtsim/flexbody/hub_spin.hpp"
#include "fowtsim/flexbody/spin_up_simulation.hpp"
#include "fowtsim/flexbody/spinning_beam.hpp"

using namespace fowtsim;

namespace {

constexpr double kEnd = 20.0;     // 15 s spin-up + 5 s at Ω_s [s]
constexpr double kSample = 0.02;  // common output grid [s]
const flexbody::HubSpin kHub = flexbody::kane_spin_up(6.0, beam::benchmarks::kKaneSpinUpTime);

// MBBT in-plane tip deflection (f's y) at t = k·kSample: modules/beam's Kane beam (same L, EI, m),
// 30 segments, Δt = 5 ms (its converged setting, rotating_verification_tests.cpp).
std::vector<double> mbbt_tip() {
  const beam::BeamModel model = beam::discretise(beam::benchmarks::kane_beam(), 30);
  beam::BeamState state = beam::make_state(model);
  beam::DynamicStepper stepper(model, beam::DynamicOptions{});
  const double dt = 0.005;
  const long per_sample = std::lround(kSample / dt), steps = std::lround(kEnd / dt);
  std::vector<double> tip{0.0};
  beam::BeamInput input;
  for (long k = 0; k < steps; ++k) {
    const double t = (static_cast<double>(k) + stepper.input_time_fraction()) * dt;
    input.frame.angular_velocity_rad_s = Vec3(0.0, 0.0, kHub.rate(t));
    input.frame.angular_acceleration_rad_s2 = Vec3(0.0, 0.0, kHub.acceleration(t));
    stepper.step(input, dt, state);
    if ((k + 1) % per_sample == 0) tip.push_back(beam::beam_outputs(model, state).tip_displacement_m.y());
  }
  return tip;
}

// flexbody RR tip with n eq. 32 modes (M_t = 0), RK4 at 1 ms.
std::vector<double> rr_tip(int n) {
  std::vector<flexbody::ShapeFunction> shapes;
  for (int j = 1; j <= n; ++j) shapes.push_back(flexbody::clamped_free_mode(j, beam::benchmarks::kKaneLength));
  const flexbody::SpinningBeam rr(flexbody::uniform_beam(beam::benchmarks::kKaneLength,
                                                         beam::benchmarks::kKaneMassPerLength,
                                                         beam::benchmarks::kKaneBendingStiffness),
                                  shapes);
  return flexbody::spin_up_tip_history(rr, kHub, kEnd, kSample, 1e-3);
}

double max_abs(const std::vector<double>& v) {
  double out = 0.0;
  for (const double x : v) out = std::max(out, std::abs(x));
  return out;
}

// RMS of a − b over the grid, divided by max |b|.
double rms_over_max(const std::vector<double>& a, const std::vector<double>& b) {
  double sq = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) sq += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(sq / static_cast<double>(a.size())) / max_abs(b);
}

}  // namespace

TEST_CASE("Kane's spin-up (seed 002 Sec. 5.2): flexbody RR with 1 and 3 modes vs the MBBT beam",
          "[verification]") {
  const std::vector<double> mbbt = mbbt_tip(), one = rr_tip(1), three = rr_tip(3);
  REQUIRE(mbbt.size() == one.size());
  REQUIRE(mbbt.size() == three.size());
  const double e1 = rms_over_max(one, mbbt), e3 = rms_over_max(three, mbbt);
  INFO("max |tip| MBBT " << max_abs(mbbt) << " m, RR-1 " << max_abs(one) << " m, RR-3 "
                         << max_abs(three) << " m; RMS difference / max |tip|: 1 mode " << e1
                         << ", 3 modes " << e3);
  // The seed finds 0.5 % (1 shape) and 0.3 % (3 shapes) relative RMS against its nonlinear
  // lumped-mass code; the MBBT beam is likewise geometrically exact, so the seed's figures are the
  // bounds. The RR drops terms of order slope² ≈ (0.57/10)² ≈ 0.3 % and the MBBT carries its own
  // O(h², Δt²) error (< 0.1 %, modules/beam README), so nothing tighter is justified.
  // Measured 0.40 % (1 mode) and 0.052 % (3 modes).
  CHECK(e1 < 0.005);
  CHECK(e3 < 0.003);
}

TEST_CASE("Kane's spin-up: flexbody RR equals modules/beam's independent RR reference",
          "[verification]") {
  // modules/beam's kane_rayleigh_ritz_tip is the same model (eq. 26 stiffening, eq. 32 modes, RK4
  // at 1 ms) coded separately with Simpson quadrature and its own β_j and hub profile. Both take
  // the same RK4 steps, so only the quadratures (< 1e-12 relative each) and rounding separate
  // them: bounded at 1e-10 of the deflection (measured 6.7e-15 m, 1.2e-14).
  const std::vector<double> ours = rr_tip(3);
  const std::vector<double> theirs = beam::benchmarks::kane_rayleigh_ritz_tip(kEnd, kSample, 3);
  REQUIRE(ours.size() == theirs.size());
  double diff = 0.0;
  for (std::size_t k = 0; k < ours.size(); ++k) diff = std::max(diff, std::abs(ours[k] - theirs[k]));
  INFO("max |difference| " << diff << " m of max |tip| " << max_abs(theirs) << " m");
  CHECK(diff < 1e-10 * max_abs(theirs));
}
