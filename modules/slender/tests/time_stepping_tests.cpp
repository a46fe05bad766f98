// The time domain as a stepping module (time_stepping.hpp) with waves in blocks (wave_blocks.hpp)
// and statistics accumulated sample by sample (statistics.hpp): the contract, a state copy that
// continues bit-identically, no allocation per step, the blocks against the whole-record synthesis
// they replace, and the online statistics against the stored-series ones.
#include "fowtsim/core/module.hpp"
#include "fowtsim/slender/statistics.hpp"
#include "fowtsim/slender/time_stepping.hpp"
#include "fowtsim/slender/wave_blocks.hpp"
#include "fowtsim/testing/allocation_counter.hpp"
#include "test_bodies.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace fowtsim::slender;
using namespace fowtsim::slender::testing;
using fowtsim::MatX;
using fowtsim::VecX;
using std::numbers::pi;

static_assert(fowtsim::Module<SlenderBody>);

namespace {

// A pinned–pinned tensioned tube (100 m, 40 strips, 8 sines, 4 modes by mode acceleration) in 120 m
// of water, with a point mass and a point spring so that every branch of the outputs runs.
Model riser() {
  BodyDescription body;
  body.strips = uniform_strips(40, 100.0, steel_tube());
  body.bottom_support = Support::Pinned;
  body.top_support = Support::Pinned;
  body.top_tension_N = 5e5;
  body.point_masses = {{60.0, 2000.0, 100.0}};
  body.point_springs = {{30.0, 1e4, 0.0}};
  body.rayleigh_mass_per_s = 0.02;
  body.shapes = pinned_pinned_shapes(8, 100.0);
  Environment env;
  env.still_water_level_m = 100.0;
  env.water_depth_m = 120.0;
  return make_model(body, env);
}

// A Pierson–Moskowitz sea (Hs 4 m, Tp 10 s) on ω_j = (first + j)Δω, record 409.6 s.
struct Sea {
  double d_omega;
  int first;
  VecX omegas, spectrum;
};
Sea sea(double record_s) {
  Sea s{2 * pi / record_s, 10, {}, {}};
  const int count = 150;
  s.omegas.resize(count);
  s.spectrum.resize(count);
  for (int j = 0; j < count; ++j) {
    s.omegas(j) = (s.first + j) * s.d_omega;
    s.spectrum(j) = pierson_moskowitz(s.omegas(j), 4.0, 10.0);
  }
  return s;
}

}  // namespace

TEST_CASE("slender blocks of a random sea equal the whole-record FFT synthesis to rounding", "[unit]") {
  const Model model = riser();
  const double interval = 0.05, record = 4096 * 2 * interval;
  const Sea s = sea(record);
  const MatXc U = velocity_transfer_table(model, s.omegas);
  const WaveComponents components = random_components(s.spectrum, s.d_omega, s.first, 7);
  const int samples = 3 * 8192 + 100;  // three records and a bit: the blocks wrap around the period
  const WaveHistory whole = random_wave_history(U, components, interval, samples);
  const WaveSource source = random_wave_source(U, components, interval);
  WaveBlockWorkspace work = make_wave_block_workspace(source);
  WaveBlock block = make_wave_block(source, U.rows());
  double worst_u = 0.0, worst_a = 0.0, worst_eta = 0.0;
  // Blocks at arbitrary starts (odd ones too), as far as the third record.
  for (long first = 0; first + source.block_samples <= samples; first += source.block_samples - 37) {
    fill_wave_block(source, first, work, block);
    const auto B = source.block_samples;
    worst_u = std::max(worst_u, (block.velocity_m_s - whole.velocity_m_s.middleCols(first, B)).cwiseAbs().maxCoeff());
    worst_a = std::max(worst_a, (block.acceleration_m_s2 - whole.acceleration_m_s2.middleCols(first, B)).cwiseAbs().maxCoeff());
    worst_eta = std::max(worst_eta, (block.elevation_m - whole.elevation_m.segment(first, B)).cwiseAbs().maxCoeff());
  }
  const double u_max = whole.velocity_m_s.cwiseAbs().maxCoeff(), a_max = whole.acceleration_m_s2.cwiseAbs().maxCoeff();
  const double eta_max = whole.elevation_m.cwiseAbs().maxCoeff();
  INFO("block length " << source.block_samples << "; max difference / max value: u " << worst_u / u_max << ", u̇ "
                       << worst_a / a_max << ", η " << worst_eta / eta_max);
  // Two exact evaluations of the same sum (FFT of the record; chirp-z over the band): they part by
  // rounding only. Measured ≤ 1.1e-15 of the peak; 1e-13 (≈ 100×: FFT rounding grows as log of the
  // lengths, which differ here by 16×).
  CHECK(worst_u < 1e-13 * u_max);
  CHECK(worst_a < 1e-13 * a_max);
  CHECK(worst_eta < 1e-13 * eta_max);
}

TEST_CASE("slender blocks of a regular wave are harmonic_wave_history's samples bit for bit", "[unit]") {
  const Model model = riser();
  const double omega = 2 * pi / 7.0, interval = 0.025;
  const VecXc U = velocity_transfer(model, omega);
  const WaveHistory whole = harmonic_wave_history(U, omega, 1.5, interval, 1000);
  const WaveSource source = harmonic_wave_source(U, omega, 1.5, interval, 64);
  WaveBlockWorkspace work = make_wave_block_workspace(source);
  WaveBlock block = make_wave_block(source, U.size());
  fill_wave_block(source, 901, work, block);
  // The same expression per sample: no tolerance.
  CHECK(block.velocity_m_s == whole.velocity_m_s.middleCols(901, 64));
  CHECK(block.acceleration_m_s2 == whole.acceleration_m_s2.middleCols(901, 64));
  CHECK(block.elevation_m == whole.elevation_m.segment(901, 64));
}

TEST_CASE("slender statistics accumulated sample by sample equal those of the stored series", "[unit]") {
  const int count = 5000;
  MatX series(3, count);
  for (int k = 0; k < count; ++k)  // a large mean beside a small spread: the case a one-pass sum of squares loses
    series.col(k) << 1e4 + std::sin(0.37 * k) + 0.2 * std::cos(1.3 * k), 3.0 * std::sin(0.1 * k + 1.0), 1e-3 * std::cos(0.05 * k);
  HarmonicSums harmonic = make_harmonic_sums(3);
  DeviationSums deviation = make_deviation_sums(3);
  const int first = 1000;
  for (int k = first; k < count; ++k) {
    add_harmonic_sample(harmonic, series.col(k), 0.37, 1.0, k);
    add_deviation_sample(deviation, series.col(k));
  }
  const VecX amplitudes = harmonic_amplitudes(harmonic), deviations = standard_deviations(deviation);
  for (int i = 0; i < 3; ++i) {
    const VecX row = series.row(i).transpose();
    // fourier_coefficient's terms in its order: bit for bit.
    CHECK(amplitudes(i) == std::abs(fourier_coefficient(row, 0.37, 1.0, first, count - first)));
    // Welford against the two-pass mean and deviation: measured ≤ 3e-14 relative (the 1e4 mean
    // row); 1e-12 (30×, rounding of 4000 updates).
    const double reference = standard_deviation(row, first, count - first);
    INFO("series " << i << ": relative difference " << deviations(i) / reference - 1.0);
    CHECK(std::abs(deviations(i) / reference - 1.0) < 1e-12);
  }
}

TEST_CASE("slender stepping: a copy of the state continues bit-identically", "[unit]") {
  const Model model = riser();
  const Modes modes = compute_modes(model, 4);
  const SlenderBody::Params p = make_time_domain_params(model, modes, Recovery::ModeAcceleration);
  const double dt = 0.05, omega = 2 * pi / 6.0;
  const WaveSource source = harmonic_wave_source(velocity_transfer(model, omega), omega, 2.0, dt / 2, 256);
  WaveBlockWorkspace work = make_wave_block_workspace(source);
  WaveBlock block = make_wave_block(source, model.strips.x_m.size());
  fill_wave_block(source, 0, work, block);
  SlenderBody::Input in = make_input(p);
  SlenderBody::State s = SlenderBody::make_state(p);
  const auto step = [&](SlenderBody::State& state) {
    in.velocity_m_s = block.velocity_m_s.middleCols(2 * state.step, 3);
    in.acceleration_m_s2 = block.acceleration_m_s2.middleCols(2 * state.step, 3);
    SlenderBody::advance(p, in, static_cast<double>(state.step) * dt, dt, state);
  };
  for (int k = 0; k < 40; ++k) step(s);
  SlenderBody::State copy = s;
  const SlenderBody::Output before = SlenderBody::outputs(p, in, s);
  for (int k = 0; k < 40; ++k) {
    step(s);
    step(copy);
  }
  CHECK(copy.step == s.step);
  CHECK(copy.a == s.a);
  CHECK(copy.a_dot == s.a_dot);
  CHECK(before.q.allFinite());
  CHECK(s.a.cwiseAbs().maxCoeff() > 0.0);  // the wave moved the body
}

TEST_CASE("slender stepping, wave blocks and statistics allocate nothing per step", "[unit]") {
  using fowtsim::testing::allocations;
  using fowtsim::testing::counting;
  const Model model = riser();
  const Modes modes = compute_modes(model, 4);
  const SlenderBody::Params p = make_time_domain_params(model, modes, Recovery::ModeAcceleration);
  const double dt = 0.05;
  const Sea s = sea(4096 * dt);
  const MatXc U = velocity_transfer_table(model, s.omegas);
  const WaveSource source = random_wave_source(U, random_components(s.spectrum, s.d_omega, s.first, 3), dt / 2);
  WaveBlockWorkspace work = make_wave_block_workspace(source);
  WaveBlock block = make_wave_block(source, U.rows());
  SlenderBody::Input in = make_input(p);
  SlenderBody::Workspace w = make_workspace(p);
  SlenderBody::Output out = make_output(p);
  SlenderBody::State state = SlenderBody::make_state(p);
  DeviationSums deviation = make_deviation_sums(U.rows());
  HarmonicSums harmonic = make_harmonic_sums(U.rows());
  fill_wave_block(source, 0, work, block);  // warm-up: FFTW's plan for the block length
  allocations = 0;
  counting = true;
  for (int k = 0; k < 2 * source.block_samples; ++k) {
    if (2 * k + 2 >= block.first_sample + source.block_samples) fill_wave_block(source, 2 * k, work, block);
    const Eigen::Index m = 2 * k - block.first_sample;
    in.velocity_m_s = block.velocity_m_s.middleCols(m, 3);
    in.acceleration_m_s2 = block.acceleration_m_s2.middleCols(m, 3);
    SlenderBody::advance(p, in, k * dt, dt, state, w);
    SlenderBody::outputs(p, in, state, w, out);
    add_deviation_sample(deviation, out.moment_inertia_relief_N_m);
    add_harmonic_sample(harmonic, out.displacement_m, 1.0, dt, k);
  }
  counting = false;
  CHECK(allocations == 0);
  CHECK(block.first_sample > 0);  // blocks were refilled inside the counted loop
  CHECK(out.moment_inertia_relief_N_m.allFinite());
}
