// The IEC Kaimal / Veers generator: exactness of the coherent sampler, determinism, and the
// statistics of generated fields (spectra, turbulence intensity, coherence) against IEC 61400-1.
#include <catch2/catch.hpp>

#include "series_support.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <random>
#include <vector>

#include "fowtsim/core/error.hpp"
#include "fowtsim/wind/coherent_sampler.hpp"
#include "fowtsim/wind/iec_turbulence.hpp"
#include "fowtsim/wind/turbulence_generator.hpp"
#include "fowtsim/wind/verification.hpp"

using namespace fowtsim;
using namespace fowtsim::wind;
using Complex = std::complex<double>;
using test_support::dft;
using test_support::series_at;

using verification::sampler_coherence_error;
using verification::small_turbulent_field;

// Intent: every way of the sampler realises the IEC coherence matrix: embedding and dense exactly
// (to round-off, tolerance 1e-12), the independent switch only where all coherences are < 1e-4.
TEST_CASE("the coherent sampler realises the IEC coherence matrix", "[verification][wind][turbulence]") {
  const int ny = 6, nz = 5;
  const double dy = 4.0, dz = 5.0;
  CoherentSampler sampler(ny, nz, dy, dz);
  CHECK(sampler.prepare(0.5) == CoherentSampler::Method::embedding);
  CHECK(sampler_coherence_error(sampler, ny, dy, dz, 0.5) < 1e-12);  // exact up to FFT round-off
  CHECK(sampler.prepare(0.002) == CoherentSampler::Method::dense);  // embedding indefinite at long range
  CHECK(sampler_coherence_error(sampler, ny, dy, dz, 0.002) < 1e-12);
  CHECK(sampler.prepare(2.5) == CoherentSampler::Method::independent);  // exp(−2.5·4) = 4.5e-5 < 1e-4
  CHECK(sampler_coherence_error(sampler, ny, dy, dz, 2.5) < CoherentSampler::independence_threshold);
  CHECK(sampler.max_dropped_coherence() == Approx(std::exp(-10.0)).epsilon(1e-12));
  // Odd sizes both ways (a centre column and row, the parity classes 4·3, 4·2, 3·3, 3·2) as the
  // 31 × 31 OC3 grid has them; its own lowest frequency's decay, a = 0.0045/m.
  CoherentSampler odd(7, 5, 4.8, 4.8);
  CHECK(odd.prepare(0.0045) == CoherentSampler::Method::dense);
  CHECK(sampler_coherence_error(odd, 7, 4.8, 4.8, 0.0045) < 1e-12);  // exact up to round-off
}

// Intent: IEC sigma_1: NTM class B at 12 m/s = 0.14 (0.75·12 + 5.6) = 2.044 m/s, as TurbSim's summary
// for the OC3 field prints ("Characteristic value of standard deviation = 2.044 m/s", 4 digits);
// ETM class I B at 12 m/s: 2·0.14·(0.072·(10/2 + 3)(12/2 − 4) + 10) = 3.12256 m/s (IEC eq. 19).
TEST_CASE("IEC NTM and ETM standard deviations", "[verification][wind][turbulence]") {
  TurbulenceParams t;
  t.category = TurbulenceCategory::B;
  CHECK(longitudinal_sigma(t, 12.0) == Approx(2.044).margin(5e-4));
  t.model = TurbulenceModel::ETM;
  t.iec_wind_class = 1;
  CHECK(longitudinal_sigma(t, 12.0) == Approx(3.12256).epsilon(1e-12));
  const KaimalModel k = kaimal_model(TurbulenceParams{}, 12.0, 90.0);
  CHECK(k.component[0].length_scale_m == Approx(340.2));  // 8.1 Λ1, Λ1 = 42 m above 60 m
  CHECK(k.component[2].sigma_m_s == Approx(0.5 * 2.044).epsilon(1e-12));
}

// Intent: MersenneTwister64 is std::mt19937_64: the same 10⁷ numbers for each of four seeds
// (0, 1, the OC3 deck's, the largest), i.e. across 32,000 state regenerations (issue 28 replaced
// the standard engine by this branch-free one in the generator: the fields must not change).
TEST_CASE("the generator's Mersenne twister draws std::mt19937_64's stream", "[unit][wind][turbulence]") {
  for (const std::uint64_t seed : {std::uint64_t{0}, std::uint64_t{1}, std::uint64_t{13428}, ~std::uint64_t{0}}) {
    MersenneTwister64 ours(seed);
    std::mt19937_64 standard(seed);
    long differing = 0;
    for (int k = 0; k < 10000000; ++k)
      if (ours() != standard()) ++differing;
    CHECK(differing == 0);  // exact: the same algorithm and parameters
  }
}

// Intent: the generator's own phasors are (cos θ, sin θ) of the same draws' phases as libm gives
// them, θ = 2π·uniform01(g), to round-off, in draw order, and of unit modulus; a batch split
// anywhere gives the same phasors (issue 28 replaced libm's sincos by a polynomial: the fields
// of every seed must stay those of before to round-off).
TEST_CASE("random phasors equal cos and sin of the draws' phases", "[unit][wind][turbulence]") {
  constexpr std::size_t count = 1000000;
  std::vector<Complex> phasors(count);
  MersenneTwister64 batch(13428);
  std::mt19937_64 reference(13428);
  fill_random_phasors(batch, phasors.data(), 1000);  // splits unaligned with the internal batch
  fill_random_phasors(batch, phasors.data() + 1000, count - 1000);
  double worst = 0.0, worst_modulus = 0.0;
  for (const Complex& p : phasors) {
    const double theta = 2.0 * std::numbers::pi * uniform01(reference);
    worst = std::max({worst, std::abs(p.real() - std::cos(theta)), std::abs(p.imag() - std::sin(theta))});
    worst_modulus = std::max(worst_modulus, std::abs(std::abs(p) - 1.0));
  }
  CHECK(worst < 7e-15);          // measured 7.2e-16 (libm's θ itself is off by up to 7e-16); ~10× that
  CHECK(worst_modulus < 2e-15);  // measured 2.2e-16 (one ulp of 1); ~10× that
  CHECK(batch() == reference());  // one draw a phasor: the streams stay in step
}

// Intent: same seed → bit-identical field (DESIGN.md §7); another seed → another field.
TEST_CASE("the generator is deterministic per seed", "[unit][wind][turbulence]") {
  const GeneratedTurbulence a = generate_turbulence(small_turbulent_field(7));
  const GeneratedTurbulence b = generate_turbulence(small_turbulent_field(7));
  const GeneratedTurbulence c = generate_turbulence(small_turbulent_field(8));
  REQUIRE(a.field.grid.size() == b.field.grid.size());
  CHECK(std::memcmp(a.field.grid.data(), b.field.grid.data(), a.field.grid.size() * sizeof(float)) == 0);
  CHECK(std::memcmp(a.field.grid.data(), c.field.grid.data(), a.field.grid.size() * sizeof(float)) != 0);
  CHECK(a.field.periodic);
  CHECK(a.stats.dense_frequencies + a.stats.embedding_frequencies + a.stats.independent_frequencies ==
        a.stats.frequencies);
}

// Intent: a field generated for a shorter run holds the whole record's first samples, bit for bit
// (the same spectra and draws; only the stored rows shrink), and a query past them stops the run
// with the time rather than wrapping around.
TEST_CASE("a field held up to a time is the whole record's beginning", "[unit][wind][turbulence]") {
  WindParams p = small_turbulent_field(7);
  p.turbulence.tower_points = true;
  const GeneratedTurbulence whole = generate_turbulence(p);
  const GeneratedTurbulence part = generate_turbulence(p, HeldTimes{100.0, 2.0});  // 600 s record, dt 0.25 s
  CHECK(part.field.nt == whole.field.nt);
  CHECK(part.field.nt_held == 402);  // samples 0 … 400 bracket 100 s, and one more
  CHECK(part.field.nt_tail == 10);   // the last 8 bracket 2 s before the start, and one more
  CHECK(whole.field.nt_held == 0);
  REQUIRE(part.field.n_tower > 0);
  const std::size_t row = static_cast<std::size_t>(p.turbulence.ny) * p.turbulence.nz * 3, tower_row = part.field.n_tower * 3;
  REQUIRE(part.field.grid.size() == 412 * row);
  const std::size_t tail_start = static_cast<std::size_t>(whole.field.nt - 10);
  CHECK(std::memcmp(part.field.grid.data(), whole.field.grid.data(), 402 * row * sizeof(float)) == 0);
  CHECK(std::memcmp(&part.field.grid[402 * row], &whole.field.grid[tail_start * row], 10 * row * sizeof(float)) == 0);
  CHECK(std::memcmp(part.field.tower.data(), whole.field.tower.data(), 402 * tower_row * sizeof(float)) == 0);
  CHECK(std::memcmp(&part.field.tower[402 * tower_row], &whole.field.tower[tail_start * tower_row], 10 * tower_row * sizeof(float)) == 0);
  validate(part.field);
  const Vec3 hub(0.0, 0.0, 90.0), downwind(20.0, 0.0, 90.0);  // 20 m downwind: 2 s earlier, the record's end at t = 0
  CHECK(full_field_velocity(part.field, hub, 99.9) == full_field_velocity(whole.field, hub, 99.9));
  CHECK(full_field_velocity(part.field, downwind, 0.1) == full_field_velocity(whole.field, downwind, 0.1));
  CHECK(full_field_velocity(part.field, downwind, 2.1) == full_field_velocity(whole.field, downwind, 2.1));  // wraps back to the head
  CHECK_THROWS_AS(full_field_velocity(part.field, hub, 100.6), NumericalError);
  CHECK_THROWS_AS(full_field_velocity(part.field, Vec3(30.0, 0.0, 90.0), 0.0), NumericalError);  // 3 s before the start
  CHECK(generate_turbulence(p, HeldTimes{595.0, 5.0}).field.nt_held == 0);  // together the whole record: all held
}

// Intent: one-point spectra of u, v, w averaged over octave bands within ±10 % of the IEC Kaimal
// target (issue 4); turbulence intensity (sigma over seeds and points) within 3 % of the record's
// target sigma = sqrt(Σ S(f_m) Δf) (issue 4; the IEC sigma itself is larger: the record carries no
// variance below 1/T or above the Nyquist frequency, as TurbSim without ScaleIEC); co-coherence of
// u at r = 20 m and 40 m against the IEC model, per octave band, within 4 standard deviations of
// the estimate, (1 − γ²)/sqrt(2K) for K independent samples (Bendat & Piersol, Random Data, 4th ed.,
// §9.2.3: random error of coherence estimates). 240 seeds of a 4×3 grid (20 m spacing), 600 s at
// 4 Hz: spectra from 4/T = 0.0067 Hz up.
TEST_CASE("generated fields have the IEC Kaimal spectra, intensity and coherence",
          "[verification][wind][turbulence]") {
  const int seeds = 240;
  const WindParams p0 = small_turbulent_field(1);
  const KaimalModel kaimal = kaimal_model(p0.turbulence, p0.speed_m_s, p0.reference_height_m);
  const int n = static_cast<int>(std::llround(p0.turbulence.duration_s / p0.turbulence.dt_s));
  const double dt = p0.turbulence.dt_s, df = 1.0 / (n * dt);
  const int top = n / 2 - 1;
  // Octave bands of bins [b, 2b) for b = 4, 8, …, and the remainder up to `top`.
  std::vector<int> band_start;
  for (int b = 4; b <= top; b *= 2) band_start.push_back(b);
  const std::size_t bands = band_start.size();
  auto band_end = [&](std::size_t i) { return std::min(2 * band_start[i], top + 1); };

  std::vector<double> measured[3], variance_sum(3, 0.0);
  for (auto& m : measured) m.assign(bands, 0.0);
  // Coherence accumulators for the u pairs (iy 0–1, 20 m) and (iy 0–2, 40 m) at iz = 1.
  const int pair_far[2] = {1, 2};
  std::vector<double> cross[2], auto_a[2], auto_b[2];
  for (int q = 0; q < 2; ++q) cross[q].assign(bands, 0.0), auto_a[q].assign(bands, 0.0), auto_b[q].assign(bands, 0.0);
  double expected_sigma[3] = {0, 0, 0};
  int series = 0;
  for (int seed = 1; seed <= seeds; ++seed) {
    const GeneratedTurbulence g = generate_turbulence(small_turbulent_field(static_cast<std::uint64_t>(seed)));
    for (int c = 0; c < 3; ++c) expected_sigma[c] = g.stats.expected_sigma_m_s[c];
    const FullField& f = g.field;
    for (int c = 0; c < 3; ++c)
      for (int iz = 0; iz < f.nz; ++iz)
        for (int iy = 0; iy < f.ny; ++iy) {
          std::vector<double> s = series_at(f, iy, iz, c);
          double mean = 0.0;
          for (double v : s) mean += v / n;
          double var = 0.0;
          for (double& v : s) v -= mean, var += v * v / n;
          variance_sum[c] += var;
          if (c == 0) ++series;
          const std::vector<Complex> x = dft(s);
          for (std::size_t i = 0; i < bands; ++i)
            for (int m = band_start[i]; m < band_end(i); ++m) measured[c][i] += 2.0 * std::norm(x[m]) * dt / n;
        }
    for (int q = 0; q < 2; ++q) {
      const std::vector<Complex> xa = dft(series_at(f, 0, 1, 0)), xb = dft(series_at(f, pair_far[q], 1, 0));
      for (std::size_t i = 0; i < bands; ++i)
        for (int m = band_start[i]; m < band_end(i); ++m) {
          cross[q][i] += (xa[m] * std::conj(xb[m])).real();
          auto_a[q][i] += std::norm(xa[m]);
          auto_b[q][i] += std::norm(xb[m]);
        }
    }
  }
  const char* names[3] = {"u", "v", "w"};
  for (int c = 0; c < 3; ++c) {
    for (std::size_t i = 0; i < bands; ++i) {
      double target = 0.0;
      for (int m = band_start[i]; m < band_end(i); ++m) target += kaimal.spectrum(c, m * df);
      const double ratio = measured[c][i] / (series * target);
      INFO(names[c] << " band from " << band_start[i] * df << " Hz: measured/target " << ratio);
      CHECK(std::abs(ratio - 1.0) < 0.10);  // ±10 % (issue 4)
    }
    const double sigma = std::sqrt(variance_sum[c] / series);
    INFO(names[c] << ": sigma " << sigma << " m/s, target " << expected_sigma[c] << " m/s, IEC " << kaimal.component[c].sigma_m_s);
    CHECK(std::abs(sigma / expected_sigma[c] - 1.0) < 0.03);  // 3 % (issue 4)
  }
  for (int q = 0; q < 2; ++q) {
    const double r = 20.0 * pair_far[q];
    for (std::size_t i = 0; i < bands; ++i) {
      // The estimate sums cross- and auto-spectra over the band, so its expectation is the
      // S_u-weighted band mean of the model: Σ S γ / Σ S.
      double target = 0.0, weight = 0.0;
      for (int m = band_start[i]; m < band_end(i); ++m) {
        target += kaimal.spectrum(0, m * df) * std::exp(-kaimal.coherence_decay_per_m(m * df) * r);
        weight += kaimal.spectrum(0, m * df);
      }
      target /= weight;
      const double estimate = cross[q][i] / std::sqrt(auto_a[q][i] * auto_b[q][i]);
      const double samples = static_cast<double>(seeds) * (band_end(i) - band_start[i]);
      const double tolerance = 4.0 * (1.0 - target * target) / std::sqrt(2.0 * samples);  // 4 sigma, see above
      INFO("r = " << r << " m, band from " << band_start[i] * df << " Hz: co-coherence " << estimate << " vs IEC "
                  << target << ", tolerance " << tolerance);
      CHECK(std::abs(estimate - target) < tolerance);
    }
  }
}

// Intent: the turbulent EWM (IEC 61400-1 ed. 3 §6.3.2.1, ed. 4 §6.3.3.2): the generator's target is
// σ1 = 0.11 V_hub (exact, one product), and the u variance generated at the hub, averaged over 200
// seeds, matches the record's σ² within 4 standard errors measured from the seeds' own spread. The
// record's σ is below 0.11 V_hub by the Kaimal variance outside [1/T, f_Nyquist] (no ScaleIEC, as
// TurbSim; 3.7 % here): against 0.11 V_hub itself the tolerance is that deficit plus the statistical
// one (half the relative variance tolerance). 40 m/s = V_1 of class I, 600 s at 4 Hz; 1 s.
TEST_CASE("the turbulent EWM generates sigma_1 = 0.11 V_hub at the hub", "[verification][wind][turbulence]") {
  const verification::EwmHubSigma e = verification::ewm_hub_sigma(200);
  CHECK(e.iec_sigma_m_s == Approx(0.11 * 40.0).epsilon(1e-15));
  const double tolerance = 4.0 * e.standard_error_m2_s2;  // 4 standard errors of the mean variance
  INFO("hub u sigma " << std::sqrt(e.mean_variance_m2_s2) << " m/s; record target " << e.record_sigma_m_s
                      << " m/s; 0.11 V_hub = " << e.iec_sigma_m_s << " m/s; tolerance on sigma² " << tolerance << " m²/s²");
  CHECK(std::abs(e.mean_variance_m2_s2 - e.record_sigma_m_s * e.record_sigma_m_s) < tolerance);
  const double deficit = 1.0 - e.record_sigma_m_s / e.iec_sigma_m_s, statistical = 0.5 * tolerance / e.mean_variance_m2_s2;
  CHECK(deficit < 0.05);  // the band [1/T, 2 Hz] holds > 90 % of the Kaimal variance at 40 m/s
  CHECK(std::abs(std::sqrt(e.mean_variance_m2_s2) / e.iec_sigma_m_s - 1.0) < deficit + statistical);
}
