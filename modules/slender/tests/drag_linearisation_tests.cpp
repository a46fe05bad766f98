// Drag linearisation on a one-DOF body (seed 004, slide "Solution in Frequency Domain" 2): a wet
// rigid cylinder on a spring, swaying in waves against quadratic Morison drag. The FD result with
// γ = (8/3π)|u_r| (regular) or √(8/π)σ_{u_r} (irregular) is an approximation of the TD solution
// with the full |u_r|u_r: the tolerances below bound the linearisation error measured here.
#include "fowtsim/slender/time_domain.hpp"
#include "test_bodies.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace fowtsim::slender;
using namespace fowtsim::slender::testing;
using std::numbers::pi;
using fowtsim::VecX;

namespace {

// 10 m long, 2 m wide cylinder, top 5 m below still water, natural period 10 s on its spring.
Model swaying_cylinder() {
  BodyDescription body;
  body.strips = uniform_strips(1, 10.0, {0.0, 2.0, 1.8, 7850.0, 2.1e11, 1.0, 1.0, 0.0});
  body.shapes = {{ShapeKind::RigidTranslation, 0, 10.0, 0.0}};
  Environment env;
  env.still_water_level_m = 15.0;
  Model probe = make_model(body, env);
  body.bottom_springs.translational_N_m = probe.mass(0, 0) * std::pow(2 * pi / 10.0, 2);
  return make_model(body, env);
}

}  // namespace

TEST_CASE("regular wave: FD with γ = (8/3π)|u_r| against the TD steady state with |u_r|u_r", "[verification]") {
  const Model model = swaying_cylinder();
  const Modes modes = compute_modes(model);
  const double period = 8.0, omega = 2 * pi / period, amplitude = 2.0, dt = period / 200;
  const VecXc U = velocity_transfer(model, omega);
  const HarmonicResponse fd = solve_harmonic(model, modes, omega, amplitude, U);
  const int steps = 200 * 60;  // 60 periods: the drag-damped transient has decayed (checked below)
  const TimeDomainResult td =
      simulate(model, modes, harmonic_wave_history(U, omega, amplitude, dt / 2, 2 * steps + 1), {dt, steps});
  const VecX sway = td.q.row(0).transpose();
  const std::complex<double> last = fourier_coefficient(sway, omega, dt, steps - 2000, 2000);
  const std::complex<double> before = fourier_coefficient(sway, omega, dt, steps - 4000, 2000);
  const double difference = std::abs(last - fd.q(0)) / std::abs(fd.q(0));
  INFO("FD |q| " << std::abs(fd.q(0)) << " TD first harmonic " << std::abs(last) << " relative difference " << difference
                 << " phase FD " << std::arg(fd.q(0)) << " TD " << std::arg(last) << " iterations " << fd.iterations);
  CHECK(std::abs(last - before) < 1e-6 * std::abs(last));  // steady state reached (measured < 1e-10)
  // Equivalent linearisation matches the drag's work per cycle on a harmonic u_r; the third
  // harmonic of |u_r|u_r it drops (≈ 1/5 of the fundamental in force) barely moves the first
  // harmonic of the response. Measured 1.25e-3 (TD lower); tolerance 1e-2 (10×, rounded).
  CHECK(difference < 1e-2);
}

TEST_CASE("irregular sea: FD with γ = √(8/π)σ_{u_r} against the RMS of long TD records", "[verification]") {
  const Model model = swaying_cylinder();
  const Modes modes = compute_modes(model);
  const double dt = 0.1, record = 4096 * dt * 2;  // one period of the synthesis: 819.2 s
  const double d_omega = 2 * pi / record;
  const int first = 20, count = 200;  // ω from 0.15 to 1.69 rad/s around Tp = 10 s
  VecX omegas(count), spectrum(count);
  for (int j = 0; j < count; ++j) {
    omegas(j) = (first + j) * d_omega;
    spectrum(j) = pierson_moskowitz(omegas(j), 4.0, 10.0);
  }
  const MatXc U = velocity_transfer_table(model, omegas);
  const RandomResponse fd = solve_random(model, modes, omegas, spectrum, d_omega, U);
  const double sigma_fd = rms_profiles(model, fd).displacement_m(0);
  const int per_record = static_cast<int>(std::lround(record / dt));
  double worst = 0.0, mean = 0.0;
  const int seeds = 4;
  for (int seed = 1; seed <= seeds; ++seed) {
    const WaveComponents components = random_components(spectrum, d_omega, first, static_cast<std::uint64_t>(seed));
    const int steps = 2 * per_record;  // first record: transient; second: statistics
    const TimeDomainResult td = simulate(model, modes, random_wave_history(U, components, dt / 2, 2 * steps + 1),
                                         {dt, steps});
    const double rms = standard_deviation(td.q.row(0).transpose(), td.q.cols() - per_record, per_record);
    worst = std::max(worst, std::abs(rms / sigma_fd - 1.0));
    mean += rms / seeds;
  }
  INFO("FD σ " << sigma_fd << " TD RMS mean over seeds " << mean << " worst seed relative difference " << worst);
  // Statistical linearisation is exact for a Gaussian response; the drag makes it slightly
  // non-Gaussian. Measured: the TD RMS is above the FD σ by 3.6e-2 on the mean of 4 seeds, 4.6e-2
  // for the worst seed (the seed-to-seed scatter of an 819 s record is part of it). Tolerance 1e-1
  // (≈ 2× the worst: the scatter does not allow a 10× margin; the linearisation's known bias is
  // a few per cent).
  CHECK(std::abs(mean / sigma_fd - 1.0) < 1e-1);
  CHECK(worst < 1e-1);
}
