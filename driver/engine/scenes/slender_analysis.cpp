#include "scenes/slender_analysis.hpp"

#include <cmath>
#include <complex>
#include <numbers>

#include "fowtsim/slender/bending_moment.hpp"
#include "fowtsim/waves/spectrum.hpp"
#include "scenes/slender_time_domain.hpp"

namespace fowtsim::driver {
namespace {

using slender::VecXc;
using Complex = std::complex<double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Amplitudes |·| of the harmonic FD response a = H/2.
SlenderProfiles harmonic_profiles(const slender::Model& model, const slender::HarmonicResponse& r) {
  const VecXc load = slender::harmonic_load_per_length(model, r);
  return profiles_with_stress(model, (model.phi * r.q).cwiseAbs(), slender::elastic_moment<Complex>(model, r.q).cwiseAbs(),
                              slender::inertia_relief_moment<Complex>(model, load, r.q, slender::harmonic_inertial_q(model, r)).cwiseAbs());
}

}  // namespace

SlenderProfiles profiles_with_stress(const slender::Model& model, VecX displacement, VecX elastic, VecX inertia_relief) {
  const VecX& Z = model.strips.section_modulus_m3;
  SlenderProfiles p{std::move(displacement), std::move(elastic), std::move(inertia_relief), {}, {}};
  p.stress_elastic_Pa = p.moment_elastic_N_m.cwiseQuotient(Z);
  p.stress_inertia_relief_Pa = p.moment_inertia_relief_N_m.cwiseQuotient(Z);
  return p;
}

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

SlenderResults solve_frequency_domain(const SlenderDeck& deck) {
  slender::Model model = slender::make_model(deck.body, deck.environment);
  slender::Modes modes = slender::compute_modes(model, deck.analysis.modes);
  SlenderResults out{std::move(model), std::move(modes), 0, {}, {}, {}};
  if (!deck.analysis.frequency_domain) return out;
  const slender::Model& m = out.model;
  const SlenderSea& sea = deck.sea;
  slender::FrequencyDomainOptions options;
  options.tolerance = deck.analysis.drag_tolerance;
  if (sea.regular) {
    const double omega = kTwoPi / sea.period_s;
    const slender::HarmonicResponse r =
        slender::solve_harmonic(m, out.modes, omega, 0.5 * sea.height_m, slender::velocity_transfer(m, omega), options);
    out.drag_iterations = r.iterations;
    out.frequency_domain = harmonic_profiles(m, r);
  } else {
    const SeaGrid grid = jonswap_grid(sea);
    const slender::MatXc table = slender::velocity_transfer_table(m, grid.omega_rad_s);
    const slender::RandomResponse r =
        slender::solve_random(m, out.modes, grid.omega_rad_s, grid.spectrum_m2_s, grid.delta_omega_rad_s, table, options);
    out.drag_iterations = r.iterations;
    out.spectra = SlenderSpectra{grid.omega_rad_s, slender::displacement_spectrum(m, r), slender::inertia_relief_spectrum(m, r)};
    const slender::RmsProfiles p = slender::rms_profiles(m, r, out.spectra->moment_inertia_relief_N2m2_s);
    out.frequency_domain = profiles_with_stress(m, p.displacement_m, p.bending_moment_N_m, p.inertia_relief_moment_N_m);
  }
  return out;
}

SlenderResults solve_slender(const SlenderDeck& deck, double dt, double t_max) {
  SlenderResults out = solve_frequency_domain(deck);
  if (!deck.analysis.time_domain) return out;
  SlenderTimeDomain time_domain(deck, out.model, out.modes, dt, std::lround(t_max / dt));
  SlenderTimeState state = time_domain.make_state();
  for (long k = 0; k < time_domain.steps(); ++k) time_domain.step(state);
  out.time_domain = time_domain.profiles(state);
  return out;
}

}  // namespace fowtsim::driver
