// `fowtsim verify pipe`: the pipe conveying fluid (seed 000 Ch. 3, modules/beam/PIPE.md) — seed
// Table 3.1 with its reference columns, and the classical stability thresholds of Païdoussis. The
// bounds are those of modules/beam/tests/pipe_tests.cpp, where each is measured and explained.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "fowtsim/beam/pipe_benchmarks.hpp"
#include "fowtsim/beam/riser.hpp"
#include "fowtsim/post/welch_psd.hpp"
#include "verify/verify_cases.hpp"

namespace fowtsim::driver {
namespace {

namespace pb = beam::pipe_benchmarks;

VerificationRow pipe_row(std::string metric, double value, double limit, std::string source) {
  return {"pipe", std::move(metric), value, fmt::format("< {:.3g}", limit), std::move(source), value < limit};
}

std::string three(const std::array<double, 3>& f) { return fmt::format("{:7.3f} {:7.3f} {:7.3f}", f[0], f[1], f[2]); }
std::string three(const std::vector<double>& f) {
  std::array<double, 3> a{0.0, 0.0, 0.0};
  std::copy_n(f.begin(), std::min<std::size_t>(3, f.size()), a.begin());
  return three(a);
}

}  // namespace

std::vector<VerificationRow> verify_pipe(std::FILE* out) {
  std::vector<VerificationRow> rows;
  fmt::print(out, "Seed Table 3.1, cantilever with flow (μ_A = 1.8e4, μ_m = 0.5035, 40 volumes): μ_ω = Im λ L² √(m/EI)\n");
  fmt::print(out, "{:>5} | {:^23} | {:^23} | {:^23} | {:^23} | {:>9} {:>9}\n", "μ_V", "ours", "Timoshenko plug flow",
             "seed", "Zhai et al.", "seed flux", "E–B ½Cor.");
  std::array<double, 3> worst{0.0, 0.0, 0.0};
  double worst_seed_flux = 0.0, first_at_rest = 0.0, first_fastest = 0.0;
  for (const pb::FlowRow& r : pb::kTable31Flow) {
    const std::vector<double> f = pb::table31_flow_frequencies(r.mu_v, false);
    const double seed_flux = pb::table31_flow_frequencies(r.mu_v, true).at(0);
    for (int k = 0; k < 3; ++k) worst[k] = std::max(worst[k], std::abs(f.at(k) / r.timoshenko[k] - 1.0));
    worst_seed_flux = std::max(worst_seed_flux, std::abs(seed_flux / r.euler_bernoulli_half_coriolis[0] - 1.0));
    if (r.mu_v == 0.0) first_at_rest = f[0];
    first_fastest = f[0];
    fmt::print(out, "{:5.2f} | {} | {} | {} | {} | {:9.4f} {:9.4f}\n", r.mu_v, three(f), three(r.timoshenko), three(r.seed),
               three(r.zhai), seed_flux, r.euler_bernoulli_half_coriolis[0]);
  }
  const std::array<double, 3> flow_bound{4e-3, 7e-3, 1e-2};
  for (int k = 0; k < 3; ++k)
    rows.push_back(pipe_row(fmt::format("Table 3.1 flow, mode {} |μ_ω/Timoshenko − 1|", k + 1), worst[k], flow_bound[k],
                            "plug-flow eq. (Païdoussis 3.38), collocation"));
  rows.push_back(pipe_row("Table 3.1 flow, seed's flux, mode 1 |μ_ω/ref − 1|", worst_seed_flux, 3e-3,
                          "E–B plug flow with half the Coriolis term"));
  rows.push_back(pipe_row("first frequency change, μ_V 0 → 1.35 (falls)", first_fastest - first_at_rest, 0.0,
                          "linear theory: flow damps and lowers mode 1"));

  fmt::print(out, "\nSeed Table 3.1, rotating cantilever (μ_A = 3.9e3, μ_m = 0, 40 volumes)\n");
  fmt::print(out, "{:>4} | {:^23} | {:^23} | {:^23} | {:^23} | {:^23}\n", "μ_Ω", "ours out of plane", "E–B flap",
             "ours in plane", "E–B lead-lag", "seed");
  const std::vector<double> rest = pb::table31_rotating_frequencies(0.0, 3).flap;
  double worst_rest = 0.0, worst_flap = 0.0, worst_lag = 0.0;
  for (int k = 0; k < 3; ++k) worst_rest = std::max(worst_rest, std::abs(rest.at(k) / pb::kTable31RotationTimoshenko[k] - 1.0));
  const pb::RotationRow& still = pb::kTable31Rotation[0];
  for (const pb::RotationRow& r : pb::kTable31Rotation) {
    const pb::RotatingFrequencies f = pb::table31_rotating_frequencies(r.mu_omega, 3);
    for (int k = 0; k < 2; ++k) {
      worst_flap = std::max(worst_flap, std::abs((f.flap.at(k) - rest[k]) - (r.flap[k] - still.flap[k])) / rest[k]);
      worst_lag = std::max(worst_lag, std::abs((f.lead_lag.at(k) - rest[k]) - (r.lead_lag[k] - still.lead_lag[k])) / rest[k]);
    }
    // A mode the classifier passed over (coupled to torsion) shows as 0, not as the next mode up.
    auto matched = [](std::vector<double> ours, const std::array<double, 3>& reference) {
      for (std::size_t k = 0; k < ours.size() && k < 3; ++k)
        if (ours[k] > 1.5 * reference[k]) ours[k] = 0.0;
      return ours;
    };
    fmt::print(out, "{:4.0f} | {} | {} | {} | {} | {}\n", r.mu_omega, three(matched(f.flap, r.flap)), three(r.flap),
               three(matched(f.lead_lag, r.lead_lag)), three(r.lead_lag), three(r.seed));
  }
  fmt::print(out, "(0: a mode not separated: near μ_Ω = 3 the third flap mode meets the first torsion mode)\n");
  rows.push_back(pipe_row("Table 3.1 rotation, at rest |μ_ω/Timoshenko − 1|", worst_rest, 7e-3, "Timoshenko cantilever, collocation"));
  rows.push_back(pipe_row("Table 3.1 rotation, flap rise − E–B rise (/f0)", worst_flap, 1e-2, "rotating E–B cantilever, collocation"));
  rows.push_back(pipe_row("Table 3.1 rotation, lead-lag rise − E–B rise (/f0)", worst_lag, 3e-2, "rotating E–B cantilever, collocation"));

  fmt::print(out, "\nSeed Table 3.2, semi-circular clamped pipe, in plane (25 volumes; μ_A over πR): μ_ω* = Im λ R² √(m/EI)\n");
  for (const bool misra : {true, false}) {
    const auto& table = misra ? pb::kTable32Misra : pb::kTable32JungChung;
    const int modes = misra ? 3 : 2;
    fmt::print(out, "μ_A = {}, μ_m = {}   {:^23} | {:^23} | {:^23}\n", misra ? "1e4" : "7.36e3", misra ? "0.5" : "0.26", "ours",
               misra ? "Misra et al. [84]" : "Jung and Chung [87]", "seed");
    double worst_curved = 0.0;
    for (const pb::CurvedRow& r : table) {
      const std::vector<double> f = pb::table32_in_plane_frequencies(misra ? 1e4 : 7.36e3, misra ? 0.5 : 0.26, r.mu_v_star, modes);
      for (int k = 0; k < modes; ++k) worst_curved = std::max(worst_curved, std::abs(f.at(k) / r.reference[k] - 1.0));
      fmt::print(out, "  μ_V* = {:.0f}                {} | {} | {}\n", r.mu_v_star, three(f), three(r.reference), three(r.seed));
    }
    rows.push_back(pipe_row(fmt::format("Table 3.2 {} |μ_ω*/ref − 1|", misra ? "μ_A 1e4" : "μ_A 7.36e3"), worst_curved, 5e-2,
                            misra ? "Misra et al. 1988 (model difference)" : "Jung & Chung (model difference)"));
  }

  // The seed's own method on our pipe: white noise on the tip, 2^17 steps of 0.5 ms (65.5 s),
  // Welch segments of 2^15 samples (bins 0.073 in μ_ω), the highest spectral peak above μ_ω = 1.
  fmt::print(out, "\nSeed's method (white-noise tip force, PSD peak of the tip; Table 3.1, 40 volumes, Δt 0.5 ms):\n");
  const post::WelchEstimator welch(1u << 15);
  auto spectrum = [&](double mu_v, bool seed_flux, double& scale) {
    beam::PipeDefinition def = pb::cantilever(1.8e4, 0.5035, mu_v);
    def.seed_momentum_flux = seed_flux;
    scale = 2.0 * std::numbers::pi * pb::dimensionless_frequency(def, 1.0);  // Hz → μ_ω
    const std::vector<double> tip = pb::white_noise_tip_response(def, 40, 5e-4, 1 << 17);
    return welch.estimate(tip, 2000.0);
  };
  auto peak = [&](const post::PowerSpectrum& p, double scale) {
    const std::vector<post::SpectralPeak> found = post::spectral_peaks(p, 1, 1.0 / scale);
    return found.empty() ? 0.0 : found.front().frequency_hz * scale;
  };
  auto density_at = [](const post::PowerSpectrum& p, double hz) {
    const double df = p.frequency_hz[1];
    return p.density[static_cast<std::size_t>(std::lround(hz / df))];
  };
  double scale = 0.0;  // the same for all three: μ_V does not change the masses
  const post::PowerSpectrum at_rest = spectrum(0.0, false, scale);
  const post::PowerSpectrum fast = spectrum(1.35, false, scale);
  const post::PowerSpectrum seed_flux = spectrum(1.35, true, scale);
  const double at_rest_peak = peak(at_rest, scale), seed_like = peak(seed_flux, scale);
  const double hump = density_at(fast, 3.1544 / scale) / density_at(fast, 0.5 * 3.1544 / scale);
  fmt::print(out, "  μ_V = 0: peak μ_ω = {:.3f} (Im λ 3.515); μ_V = 1.35: PSD(Im λ = 3.154)/PSD(1.577) = {:.3f} "
                  "(no resonant hump: ζ = 0.52); with the seed's flux: peak {:.3f} (the seed's 3.82)\n",
             at_rest_peak, hump, seed_like);
  rows.push_back(pipe_row("seed's method, μ_V = 0: |PSD peak − Im λ|", std::abs(at_rest_peak - 3.5150), 0.1,
                          "PSD bin 0.073: the method's resolution"));
  rows.push_back(pipe_row("seed's method, μ_V = 1.35: PSD(ω_d)/PSD(ω_d/2)", hump, 1.0,
                          "flow damps mode 1 (ζ 0.52): no peak to read"));
  rows.push_back(pipe_row("seed's method, seed's flux, μ_V = 1.35: |peak/3.82 − 1|", std::abs(seed_like / 3.82 - 1.0), 5e-2,
                          "seed Table 3.1 (its flux reproduces its trend)"));

  const double flutter = pb::instability_threshold(1e5, pb::kFlutterBeta, beam::EndCondition::free, 40, 5.0, 6.5, 1e-3);
  const double pinned = pb::instability_threshold(1e5, 0.5, beam::EndCondition::pinned, 40, 2.5, 4.0, 1e-4);
  const double clamped = pb::instability_threshold(1e5, 0.5, beam::EndCondition::clamped, 40, 5.5, 7.0, 1e-4);
  fmt::print(out, "\nStability thresholds (μ_A = 1e5, 40 volumes): cantilever flutter β = 0.2 u_cf = {:.4f} (Gregory & Païdoussis "
                  "≈ 5.6, collocation {:.4f}); divergence pinned-pinned {:.5f} (π), clamped-clamped {:.5f} (2π)\n\n",
             flutter, pb::kFlutterEulerBernoulli, pinned, clamped);
  rows.push_back(pipe_row("cantilever flutter β = 0.2, |u_cf − 5.5914|", std::abs(flutter - pb::kFlutterEulerBernoulli), 3e-2,
                          "Païdoussis vol. 1 p. 112 (≈ 5.6); collocation"));
  rows.push_back(pipe_row("pinned-pinned divergence |u/π − 1|", std::abs(pinned / std::numbers::pi - 1.0), 4e-3,
                          "Païdoussis vol. 1 §3.3.6"));
  rows.push_back(pipe_row("clamped-clamped divergence |u/2π − 1|", std::abs(clamped / (2.0 * std::numbers::pi) - 1.0), 2e-2,
                          "Païdoussis vol. 1 §3.3.6"));

  // Seed §3.5.3's riser, cases (a)–(d) (modules/beam/riser.hpp; bounds as in riser_tests.cpp):
  // the seed states its conclusions in words, checked here in numbers.
  beam::riser::RiserRun riser[4];
  for (int k = 0; k < 4; ++k) riser[k] = beam::riser::simulate(beam::riser::seed_case(static_cast<char>('a' + k)), 100, 1e-3, 11.0, {});
  auto riser_peak = [&](int k) { return riser[k].max_bending_moment_n_m_overall; };
  fmt::print(out, "Riser (seed §3.5.3, 100 volumes, Δt 1 ms, 11 s): max |M| (a) {:.4e}, (b) {:.4e}, (c) {:.4e}, (d) {:.4e} N·m; "
                  "max deflection (a) {:.3f}, (b) {:.3f}, (c) {:.3f}, (d) {:.3f} m\n\n",
             riser_peak(0), riser_peak(1), riser_peak(2), riser_peak(3), riser[0].max_deflection_m, riser[1].max_deflection_m, riser[2].max_deflection_m,
             riser[3].max_deflection_m);
  rows.push_back(pipe_row("riser max |M| (a)/(b): tension stiffens", riser_peak(0) / riser_peak(1), 0.8, "seed §3.5.3 (words; Fig. 3.12)"));
  rows.push_back(pipe_row("riser |max |M| (c)/(b) − 1|: flow μ_v 1.07 hardly matters", std::abs(riser_peak(2) / riser_peak(1) - 1.0), 2e-2,
                          "seed §3.5.3 (words; Fig. 3.11)"));
  rows.push_back(pipe_row("riser max |M| (d)/(c): pressure raises bending", riser_peak(3) / riser_peak(2), 1.0 / 1.1, "seed §3.5.3 (words; Fig. 3.12)"));
  return rows;
}

}  // namespace fowtsim::driver
