#include "scenes/slender_time_domain.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "scenes/slender_analysis.hpp"

namespace fowtsim::driver {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// A regular wave's samples are analytic: a block is only how many are formed at a time.
constexpr Eigen::Index kRegularBlockSamples = 256;

slender::WaveSource wave_source(const SlenderSea& sea, const slender::Model& m, double dt) {
  if (sea.regular) {
    const double omega = kTwoPi / sea.period_s;
    return slender::harmonic_wave_source(slender::velocity_transfer(m, omega), omega, 0.5 * sea.height_m, 0.5 * dt,
                                         kRegularBlockSamples);
  }
  const SeaGrid grid = jonswap_grid(sea);
  return slender::random_wave_source(
      slender::velocity_transfer_table(m, grid.omega_rad_s),
      slender::random_components(grid.spectrum_m2_s, grid.delta_omega_rad_s, grid.first_index, sea.seed), 0.5 * dt);
}

// The statistics' first step: the window is every step after the transient; a regular wave's, the
// last whole number of wave periods in it (the Fourier coefficient of one harmonic needs whole periods).
long window_first(const SlenderDeck& deck, double dt, long steps) {
  const SlenderSea& sea = deck.sea;
  long count = steps - static_cast<long>(std::ceil(deck.analysis.transient_s / dt - 1e-9)) + 1;
  if (sea.regular) {
    const long per_period = std::lround(sea.period_s / dt);
    count = (count - 1) / per_period * per_period;
  }
  if (count < 2)
    throw InputError({"slender", std::nullopt, "analysis.transient_s", "less than the simulated time by a wave period or more"},
                     fmt::format("the time domain keeps no {} after a transient of {} s in {} s", sea.regular ? "whole wave period" : "samples",
                                 deck.analysis.transient_s, static_cast<double>(steps) * dt));
  return steps + 1 - count;
}

}  // namespace

SlenderTimeDomain::SlenderTimeDomain(const SlenderDeck& deck, const slender::Model& model, const slender::Modes& modes, double dt,
                                     long steps)
    : sea_(deck.sea),
      dt_s_(dt),
      steps_(steps),
      window_first_(window_first(deck, dt, steps)),
      params_(slender::make_time_domain_params(model, modes, slender::Recovery::ModeAcceleration)),
      waves_(wave_source(deck.sea, model, dt)),
      wave_work_(slender::make_wave_block_workspace(waves_)),
      input_(slender::make_input(params_)),
      work_(slender::make_workspace(params_)),
      output_(slender::make_output(params_)) {}

SlenderTimeState SlenderTimeDomain::make_state() {
  const Eigen::Index N = params_.model.strips.x_m.size(), regular = sea_.regular ? N : 0, random = sea_.regular ? 0 : N;
  SlenderTimeState s{slender::SlenderBody::make_state(params_), slender::make_wave_block(waves_, N), {}, {}};
  for (auto& h : s.harmonic) h = slender::make_harmonic_sums(regular);
  for (auto& d : s.deviation) d = slender::make_deviation_sums(random);
  slender::fill_wave_block(waves_, 0, wave_work_, s.waves);
  accumulate(s);
  return s;
}

void SlenderTimeDomain::load_input(const SlenderTimeState& s, int columns) {
  const slender::WaveBlock& b = s.waves;
  for (int c = 0; c < columns; ++c) {
    const Eigen::Index m = 2 * s.body.step + c - b.first_sample;  // in the block: step() keeps it there
    input_.velocity_m_s.col(c) = b.velocity_m_s.col(m);
    input_.acceleration_m_s2.col(c) = b.acceleration_m_s2.col(m);
  }
}

void SlenderTimeDomain::step(SlenderTimeState& s) {
  const long k = s.body.step;
  // The step takes samples 2k, 2k + 1, 2k + 2 (RK4's start, midpoint, end); a block starts at an
  // even sample, so the row after the step finds its sample 2k + 2 in the same block.
  if (2 * k + 2 >= s.waves.first_sample + waves_.block_samples) slender::fill_wave_block(waves_, 2 * k, wave_work_, s.waves);
  load_input(s, 3);
  slender::SlenderBody::advance(params_, input_, static_cast<double>(k) * dt_s_, dt_s_, s.body, work_);
  accumulate(s);
}

void SlenderTimeDomain::accumulate(SlenderTimeState& s) {
  const long k = s.body.step;
  if (k < window_first_) return;
  const slender::SlenderBody::Output& out = outputs(s);
  const VecX* series[3] = {&out.displacement_m, &out.moment_elastic_N_m, &out.moment_inertia_relief_N_m};
  for (int q = 0; q < 3; ++q) {
    if (sea_.regular)
      slender::add_harmonic_sample(s.harmonic[q], *series[q], kTwoPi / sea_.period_s, dt_s_, k);
    else
      slender::add_deviation_sample(s.deviation[q], *series[q]);
  }
}

const slender::SlenderBody::Output& SlenderTimeDomain::outputs(const SlenderTimeState& s) {
  load_input(s, 1);
  slender::SlenderBody::outputs(params_, input_, s.body, work_, output_);
  return output_;
}

double SlenderTimeDomain::wave_elevation_m(const SlenderTimeState& s) const {
  return s.waves.elevation_m(2 * s.body.step - s.waves.first_sample);
}

SlenderProfiles SlenderTimeDomain::profiles(const SlenderTimeState& s) const {
  if (s.body.step != steps_)
    throw std::logic_error(fmt::format("slender time domain: profiles asked at step {} of {}", s.body.step, steps_));
  const auto profile = [&](int q) {
    return sea_.regular ? slender::harmonic_amplitudes(s.harmonic[q]) : slender::standard_deviations(s.deviation[q]);
  };
  return profiles_with_stress(params_.model, profile(0), profile(1), profile(2));
}

}  // namespace fowtsim::driver
