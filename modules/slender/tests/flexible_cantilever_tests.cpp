// A clamped, riser-like flexible cantilever standing in 60 m of water (50 m steel tube, top 10 m
// below still water): FD against TD (seed 004 slides "Preliminary results for a flexible marine
// riser": FD and TD agree), mode acceleration against mode displacement (slide "Solution in
// Frequency Domain"), and the bending moment by EI v'' against inertia relief (slide "Bending
// Moment": "both 'EI' and 'IR' can be used as 2nd derivative is available for flexible structure").
#include "fowtsim/slender/bending_moment.hpp"
#include "fowtsim/slender/time_domain.hpp"
#include "test_bodies.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <numbers>
#include <utility>

using namespace fowtsim::slender;
using namespace fowtsim::slender::testing;
using fowtsim::VecX;
using std::numbers::pi;

namespace {

constexpr double kLength = 50.0;

// Mass-proportional damping α only (5 % of critical in mode 1): an external force, so the
// inertia-relief and elastic moments are comparable in the TD too. cd = 0: linear damping only.
Model cantilever(int shapes, double cd, double alpha, int strips = 100) {
  BodyDescription body;
  Strip tube = steel_tube();
  tube.drag_coefficient = cd;
  body.strips = uniform_strips(strips, kLength, tube);
  body.bottom_support = Support::Clamped;
  body.shapes = clamped_free_shapes(shapes, kLength);
  body.rayleigh_mass_per_s = alpha;
  Environment env;
  env.still_water_level_m = kLength + 10.0;
  env.water_depth_m = kLength + 10.0;
  return make_model(body, env);
}

double alpha_for_five_percent() { return 2 * 0.05 * compute_modes(cantilever(6, 0.0, 0.0), 1).omega_rad_s(0); }

}  // namespace

TEST_CASE("flexible cantilever, regular wave, linear damping: FD equals the TD steady state", "[verification]") {
  const Model model = cantilever(6, 0.0, alpha_for_five_percent());
  const Modes modes = compute_modes(model, 3);
  const double period = 5.0, omega = 2 * pi / period, dt = 0.01, amplitude = 1.5;
  const VecXc U = velocity_transfer(model, omega);
  const HarmonicResponse fd = solve_harmonic(model, modes, omega, amplitude, U);
  const int steps = 50000, window = 2000;  // 500 s: transient e^{−ζω₁t} < 1e-9; last 4 periods
  const TimeDomainResult td =
      simulate(model, modes, harmonic_wave_history(U, omega, amplitude, dt / 2, 2 * steps + 1), {dt, steps});
  const auto N = model.strips.x_m.size();
  const VecXc v_fd = model.phi * fd.q;
  const VecXc m_fd = elastic_moment<std::complex<double>>(model, fd.q);
  const std::complex<double> top_td = fourier_coefficient(td.displacement_m.row(N - 1).transpose(), omega, dt, steps - window, window);
  const std::complex<double> base_td = fourier_coefficient(td.moment_elastic_N_m.row(0).transpose(), omega, dt, steps - window, window);
  const double top_error = std::abs(top_td - v_fd(N - 1)) / std::abs(v_fd(N - 1));
  const double base_error = std::abs(base_td - m_fd(0)) / std::abs(m_fd(0));
  INFO("top |v| FD " << std::abs(v_fd(N - 1)) << " TD " << std::abs(top_td) << " rel " << top_error << "; base |M| FD "
                     << std::abs(m_fd(0)) << " TD " << std::abs(base_td) << " rel " << base_error);
  // Same linear equations, so only RK4's error (Δt = 0.01 s, ω₃Δt ≈ 0.16) and the decayed
  // transient separate them. Measured 4.4e-10 (top), 4.8e-10 (base); tolerance 5e-9 (10×).
  CHECK(top_error < 5e-9);
  CHECK(base_error < 5e-9);
}

TEST_CASE("mode acceleration with 2 modes is closer to the all-mode answer than mode displacement", "[verification]") {
  const Model model = cantilever(8, 1.0, 0.0);
  const double omega = 2 * pi / 6.0, amplitude = 2.0;
  const VecXc U = velocity_transfer(model, omega);
  const HarmonicResponse full = solve_harmonic(model, compute_modes(model), omega, amplitude, U);
  const Modes two = compute_modes(model, 2);
  const HarmonicResponse ma = solve_harmonic(model, two, omega, amplitude, U, {Recovery::ModeAcceleration});
  const HarmonicResponse md = solve_harmonic(model, two, omega, amplitude, U, {Recovery::ModeDisplacement});
  const VecXc reference = elastic_moment<std::complex<double>>(model, full.q);
  const auto error = [&](const HarmonicResponse& r) {
    return (elastic_moment<std::complex<double>>(model, r.q) - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
  };
  INFO("moment error: mode acceleration " << error(ma) << ", mode displacement " << error(md));
  // Measured 2.8e-5 (MA) and 4.3e-3 (MD): the quasi-static part of modes 3–8 that MA keeps.
  // Tolerances 3e-4 (10×) and MA at least 10× better than MD.
  CHECK(error(ma) < 3e-4);
  CHECK(error(ma) < error(md) / 10.0);
}

TEST_CASE("bending moment by EI v'' against inertia relief, FD with linearised drag", "[verification]") {
  const double omega = 2 * pi / 6.0, amplitude = 2.0;
  double previous = 1.0;
  for (const auto& [shapes, strips] : {std::pair{4, 100}, std::pair{8, 400}, std::pair{16, 1600}}) {
    const Model model = cantilever(shapes, 1.0, 0.0, strips);
    const HarmonicResponse r = solve_harmonic(model, compute_modes(model), omega, amplitude, velocity_transfer(model, omega));
    const VecXc elastic = elastic_moment<std::complex<double>>(model, r.q);
    const VecXc relief = inertia_relief_moment<std::complex<double>>(model, harmonic_load_per_length(model, r), r.q, harmonic_inertial_q(model, r));
    const double difference = (elastic - relief).cwiseAbs().maxCoeff() / elastic.cwiseAbs().maxCoeff();
    INFO(shapes << " shapes, " << strips << " strips: max |EI v'' − IR| / max |M| = " << difference);
    // Largest at the clamped base. Measured 2.2e-3, 5.7e-4, 1.5e-4 for (4, 100), (8, 400),
    // (16, 1600): the Ritz solution satisfies the force balance only weakly (falls with the shapes)
    // and the strip sums are a midpoint rule (falls with the strips); refining one alone stalls
    // (8 shapes: 2.1e-3, 5.7e-4, 4.9e-4 for 100, 400, 1600 strips). Tolerance for the finest: 1.5e-3.
    CHECK(difference < previous);
    if (shapes == 16) CHECK(difference < 1.5e-3);
    previous = difference;
  }
}

TEST_CASE("bending moment by EI v'' against inertia relief, TD with nonlinear drag", "[verification]") {
  const Model model = cantilever(8, 1.0, alpha_for_five_percent(), 400);
  const Modes modes = compute_modes(model);
  const double omega = 2 * pi / 6.0, dt = 0.01;
  const int steps = 3000;
  const TimeDomainResult td = simulate(
      model, modes, harmonic_wave_history(velocity_transfer(model, omega), omega, 2.0, dt / 2, 2 * steps + 1), {dt, steps});
  const double scale = td.moment_elastic_N_m.cwiseAbs().maxCoeff();
  const double difference = (td.moment_elastic_N_m - td.moment_inertia_relief_N_m).cwiseAbs().maxCoeff() / scale;
  INFO("max |EI v'' − IR| / max |M| over 30 s = " << difference);
  // Measured 5.6e-4 with 8 shapes on 400 strips (5.7e-4 in the FD case); tolerance 6e-3 (10×).
  CHECK(difference < 6e-3);
}

TEST_CASE("performance: one FD case of the cantilever (printed, not asserted)", "[verification]") {
  const Model model = cantilever(8, 1.0, 0.0);
  const Modes modes = compute_modes(model, 4);
  VecX omegas(100), spectrum(100);
  for (int j = 0; j < 100; ++j) {
    omegas(j) = 0.2 + 0.02 * j;
    spectrum(j) = pierson_moskowitz(omegas(j), 4.0, 10.0);
  }
  const MatXc U = velocity_transfer_table(model, omegas);
  // Best of five: the machine is shared, the least disturbed run is the cost.
  double solve_ms = INFINITY, profiles_ms = INFINITY;
  RandomResponse r;
  RmsProfiles p;
  for (int k = 0; k < 5; ++k) {
    const auto start = std::chrono::steady_clock::now();
    r = solve_random(model, modes, omegas, spectrum, 0.02, U);
    const auto solved = std::chrono::steady_clock::now();
    p = rms_profiles(model, r);
    const auto end = std::chrono::steady_clock::now();
    solve_ms = std::min(solve_ms, std::chrono::duration<double, std::milli>(solved - start).count());
    profiles_ms = std::min(profiles_ms, std::chrono::duration<double, std::milli>(end - solved).count());
  }
  std::cout << "slender FD, 100 strips, 8 shapes, 4 modes, 100 frequencies, " << r.iterations << " drag iterations: solve "
            << solve_ms << " ms, rms profiles " << profiles_ms << " ms (best of 5; base σ_stress " << p.stress_Pa(0) / 1e6 << " MPa)\n";
  CHECK(p.stress_Pa.allFinite());
}
