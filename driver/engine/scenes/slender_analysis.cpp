#include "scenes/slender_analysis.hpp"

#include <cmath>
#include <complex>
#include <numbers>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/slender/bending_moment.hpp"
#include "fowtsim/slender/statistics.hpp"
#include "fowtsim/waves/spectrum.hpp"

namespace fowtsim::driver {
namespace {

using slender::VecXc;
using Complex = std::complex<double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

SlenderProfiles with_stress(const slender::Model& model, VecX displacement, VecX elastic, VecX inertia_relief) {
  const VecX& Z = model.strips.section_modulus_m3;
  SlenderProfiles p{std::move(displacement), std::move(elastic), std::move(inertia_relief), {}, {}};
  p.stress_elastic_Pa = p.moment_elastic_N_m.cwiseQuotient(Z);
  p.stress_inertia_relief_Pa = p.moment_inertia_relief_N_m.cwiseQuotient(Z);
  return p;
}

// Amplitudes |·| of the harmonic FD response a = H/2.
SlenderProfiles harmonic_profiles(const slender::Model& model, const slender::HarmonicResponse& r) {
  const VecXc load = slender::harmonic_load_per_length(model, r);
  return with_stress(model, (model.phi * r.q).cwiseAbs(), slender::elastic_moment<Complex>(model, r.q).cwiseAbs(),
                     slender::inertia_relief_moment<Complex>(model, load, r.q, slender::harmonic_inertial_q(model, r)).cwiseAbs());
}

// Per strip (row) of a TD history: |first harmonic| over the window (regular) or σ (random).
VecX row_statistic(const MatX& history, const SlenderSea& sea, double dt, Eigen::Index first, Eigen::Index count) {
  VecX out(history.rows());
  for (Eigen::Index i = 0; i < history.rows(); ++i) {
    const VecX row = history.row(i).transpose();
    out(i) = sea.regular ? std::abs(slender::fourier_coefficient(row, kTwoPi / sea.period_s, dt, first, count))
                         : slender::standard_deviation(row, first, count);
  }
  return out;
}

}  // namespace

double profile_difference(const VecX& reference, const VecX& other) {
  return (other - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
}

SeaGrid jonswap_grid(const SlenderSea& sea) {
  SeaGrid g;
  g.delta_omega_rad_s = kTwoPi / sea.record_s;
  g.first_index = std::max(1, static_cast<int>(std::ceil(sea.min_omega_rad_s / g.delta_omega_rad_s - 1e-9)));
  const int last = static_cast<int>(std::floor(sea.max_omega_rad_s / g.delta_omega_rad_s + 1e-9));
  const int count = std::max(0, last - g.first_index + 1);
  g.omega_rad_s = VecX::LinSpaced(count, g.first_index, last) * g.delta_omega_rad_s;
  // C(γ) once: it is an integral over the spectrum's shape (most of a frequency-domain case's time
  // if taken at every ω).
  const double normalisation = waves::jonswap_normalisation(sea.gamma);
  g.spectrum_m2_s = g.omega_rad_s.unaryExpr(
      [&](double w) { return waves::jonswap_density(w, sea.hs_m, sea.tp_s, sea.gamma, normalisation); });
  return g;
}

SlenderResults solve_slender(const SlenderDeck& deck, double dt, double t_max) {
  slender::Model model = slender::make_model(deck.body, deck.environment);
  slender::Modes modes = slender::compute_modes(model, deck.analysis.modes);
  SlenderResults out{std::move(model), std::move(modes), 0, {}, {}, {}, {}, {}};
  const slender::Model& m = out.model;
  const SlenderSea& sea = deck.sea;
  const double omega = sea.regular ? kTwoPi / sea.period_s : 0.0, amplitude = 0.5 * sea.height_m;
  const SeaGrid grid = sea.regular ? SeaGrid{} : jonswap_grid(sea);
  const VecXc U = sea.regular ? slender::velocity_transfer(m, omega) : VecXc{};
  const slender::MatXc table = sea.regular ? slender::MatXc{} : slender::velocity_transfer_table(m, grid.omega_rad_s);

  if (deck.analysis.frequency_domain) {
    slender::FrequencyDomainOptions options;
    options.tolerance = deck.analysis.drag_tolerance;
    if (sea.regular) {
      const slender::HarmonicResponse r = slender::solve_harmonic(m, out.modes, omega, amplitude, U, options);
      out.drag_iterations = r.iterations;
      out.frequency_domain = harmonic_profiles(m, r);
    } else {
      const slender::RandomResponse r =
          slender::solve_random(m, out.modes, grid.omega_rad_s, grid.spectrum_m2_s, grid.delta_omega_rad_s, table, options);
      out.drag_iterations = r.iterations;
      out.spectra = SlenderSpectra{grid.omega_rad_s, slender::displacement_spectrum(m, r), slender::inertia_relief_spectrum(m, r)};
      const slender::RmsProfiles p = slender::rms_profiles(m, r, out.spectra->moment_inertia_relief_N2m2_s);
      out.frequency_domain = with_stress(m, p.displacement_m, p.bending_moment_N_m, p.inertia_relief_moment_N_m);
    }
  }
  if (!deck.analysis.time_domain) return out;

  const int steps = static_cast<int>(std::lround(t_max / dt));
  const int samples = 2 * steps + 1;  // RK4 takes the waves at every half step
  const slender::WaveHistory waves =
      sea.regular ? slender::harmonic_wave_history(U, omega, amplitude, 0.5 * dt, samples)
                  : slender::random_wave_history(
                        table, slender::random_components(grid.spectrum_m2_s, grid.delta_omega_rad_s, grid.first_index, sea.seed),
                        0.5 * dt, samples);
  out.history = slender::simulate(m, out.modes, waves, {dt, steps});
  out.wave_elevation_m = Eigen::Map<const VecX, 0, Eigen::InnerStride<2>>(waves.elevation_m.data(), steps + 1);

  // The statistics window: the samples after the transient; a regular wave's, the last whole
  // number of wave periods in it (the Fourier coefficient of one harmonic needs whole periods).
  Eigen::Index count = steps - static_cast<Eigen::Index>(std::ceil(deck.analysis.transient_s / dt - 1e-9)) + 1;
  if (sea.regular) {
    const Eigen::Index per_period = std::lround(sea.period_s / dt);
    count = (count - 1) / per_period * per_period;
  }
  if (count < 2)
    throw InputError({"slender", std::nullopt, "analysis.transient_s", "less than the simulated time by a wave period or more"},
                     fmt::format("the time domain keeps no {} after a transient of {} s in {} s", sea.regular ? "whole wave period" : "samples",
                                 deck.analysis.transient_s, t_max));
  const Eigen::Index first = steps + 1 - count;
  const slender::TimeDomainResult& h = *out.history;
  out.time_domain = with_stress(m, row_statistic(h.displacement_m, sea, dt, first, count),
                                row_statistic(h.moment_elastic_N_m, sea, dt, first, count),
                                row_statistic(h.moment_inertia_relief_N_m, sea, dt, first, count));
  return out;
}

}  // namespace fowtsim::driver
