// Irregular-sea synthesis: statistics of 3-hour records (Hs, spectral peak), FFT vs summation,
// periodicity, cut-offs, determinism.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/core/fft.hpp"
#include "fowtsim/waves/precomputed_kinematics.hpp"
#include "fowtsim/waves/spectrum.hpp"
#include "test_waves.hpp"

using namespace waves_test;

namespace {

// One-sided periodogram [m²/Hz] of a real record of length D: P_n = 2 |Y_n|² / N² · D at f_n = n/D.
std::vector<double> periodogram(const std::vector<double>& x, double duration) {
  const std::size_t n = x.size();
  fowtsim::ForwardRealFft fft(n);
  std::copy(x.begin(), x.end(), fft.samples());
  const std::complex<double>* out = fft.execute();
  std::vector<double> p(n / 2 + 1);
  for (std::size_t k = 0; k < p.size(); ++k) p[k] = 2.0 * std::norm(out[k]) / (double(n) * double(n)) * duration;
  return p;
}

// Frequency [Hz] of the maximum of the periodogram smoothed by a centred box of 2 half + 1 bins.
double smoothed_peak_hz(const std::vector<double>& p, double duration, std::size_t half) {
  double best = -1.0;
  std::size_t best_bin = 0;
  for (std::size_t k = half + 1; k + half < p.size(); ++k) {
    double s = 0.0;
    for (std::size_t j = k - half; j <= k + half; ++j) s += p[j];
    if (s > best) best = s, best_bin = k;
  }
  return static_cast<double>(best_bin) / duration;
}

double variance(const std::vector<double>& x) {
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  double var = 0.0;
  for (double v : x) var += (v - mean) * (v - mean);
  return var / static_cast<double>(x.size());
}

}  // namespace

TEST_CASE("a 3-hour JONSWAP record reproduces Hs and the spectral peak", "[verification][waves]") {
  // Issue check: Hs 6 m, Tp 10 s, γ 3.3, deep water, 3 h at dt 0.25 s (Δf = 1/10800 Hz).
  const WaveParams p = jonswap(6.0, 10.0, 3.3, kInf);
  const WaveField field(p);
  const std::vector<double> eta = field.elevation_series(0.0, 0.0);
  REQUIRE(eta.size() == 43200);
  // Hs = 4 √m0 of the time series within 2 % (issue). With deterministic amplitudes the record's
  // variance is Σ S Δω: only the tail above Nyquist (2 Hz) is missing, ~(fp/fN)⁴/5 ≈ 1e-6 of m0.
  const double hs = 4.0 * std::sqrt(variance(eta));
  CHECK(hs == Approx(6.0).epsilon(0.02));
  CHECK(hs == Approx(6.0).epsilon(1e-5));  // measured 2.6e-6
  CHECK(variance(eta) == Approx(field.record_m0_m2()).epsilon(1e-12));  // Parseval
  // Peak of the periodogram smoothed over 21 bins (±10 bins = ±9.3e-4 Hz): at 1/Tp within the
  // stated resolution, half the window plus one bin = 11/D = 1.0e-3 Hz.
  const std::vector<double> psd = periodogram(eta, p.duration_s);
  const double resolution = 11.0 / p.duration_s;
  CHECK(std::abs(smoothed_peak_hz(psd, p.duration_s, 10) - 0.1) <= resolution);
  // The periodogram equals the target spectrum S_f(f) = 2π S(ω) at every bin (deterministic
  // amplitudes, record exactly periodic: no leakage). Check near the peak.
  for (std::size_t n : {800u, 1080u, 1300u, 3000u}) {
    const double f = n / p.duration_s;
    CHECK(psd[n] == Approx(2.0 * kPi * jonswap_density(2.0 * kPi * f, 6.0, 10.0, 3.3)).epsilon(1e-9));
  }
}

TEST_CASE("a 3-hour Pierson-Moskowitz record reproduces Hs and the spectral peak", "[verification][waves]") {
  WaveParams p = jonswap(6.0, 10.0, 1.0, kInf);
  p.model = WaveModel::pierson_moskowitz;
  p.gamma.reset();
  const WaveField field(p);
  const std::vector<double> eta = field.elevation_series(0.0, 0.0);
  CHECK(4.0 * std::sqrt(variance(eta)) == Approx(6.0).epsilon(0.02));
  CHECK(4.0 * std::sqrt(variance(eta)) == Approx(6.0).epsilon(1e-5));  // measured 3.9e-6
  // PM's peak is flat (no enhancement): a wider window, ±50 bins, and resolution 51/D = 4.7e-3 Hz.
  const std::vector<double> psd = periodogram(eta, p.duration_s);
  CHECK(std::abs(smoothed_peak_hz(psd, p.duration_s, 50) - 0.1) <= 51.0 / p.duration_s);
}

TEST_CASE("Rayleigh amplitudes: Hs and peak within their sampling scatter", "[verification][waves]") {
  // With Rayleigh amplitudes each a²/2 is exponential with mean S Δω, so the record variance
  // scatters with relative standard deviation √(Σ (S Δω)²)/Σ S Δω. Tolerance: 4 of those
  // standard deviations (on Hs: half the relative scatter of m0).
  WaveParams p = jonswap(6.0, 10.0, 3.3, kInf);
  p.rayleigh_amplitudes = true;
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    p.seed = seed;
    const WaveField field(p);
    double sum = 0.0, sum_sq = 0.0;
    const double d_omega = 2.0 * kPi / p.duration_s;
    const double c = jonswap_normalisation(3.3);
    for (const WaveComponent& w : field.components()) {
      const double s = jonswap_density(w.omega_rad_s, 6.0, 10.0, 3.3, c) * d_omega;
      sum += s;
      sum_sq += s * s;
    }
    const double relative_sd_m0 = std::sqrt(sum_sq) / sum;  // 0.037 here
    const std::vector<double> eta = field.elevation_series(0.0, 0.0);
    const double hs = 4.0 * std::sqrt(variance(eta));
    INFO("seed " << seed << " Hs " << hs << " relative sd of m0 " << relative_sd_m0);
    CHECK(std::abs(hs / 6.0 - 1.0) <= 4.0 * 0.5 * relative_sd_m0);
    // Peak of the periodogram smoothed over ±50 bins (±4.6e-3 Hz): within 1/D · 51 = 4.7e-3 Hz.
    const std::vector<double> psd = periodogram(eta, p.duration_s);
    CHECK(std::abs(smoothed_peak_hz(psd, p.duration_s, 50) - 0.1) <= 51.0 / p.duration_s);
  }
}

TEST_CASE("FFT synthesis equals summation over components on the record grid", "[verification][waves]") {
  WaveParams p = jonswap(3.0, 7.0, 2.0, 60.0, 600.0, 0.2, 11);
  p.heading_deg = 40.0;
  const WaveField field(p);
  for (std::size_t m : {1u, 3u}) {
    const std::vector<double> eta = field.elevation_series(12.0, -5.0, m);
    REQUIRE(eta.size() == field.record_samples() * m);
    const double dt = field.record_dt_s() / double(m);
    double worst = 0.0;
    for (std::size_t j = 0; j < eta.size(); j += 37) worst = std::max(worst, std::abs(eta[j] - field.elevation(12.0, -5.0, j * dt)));
    CHECK(worst <= 3e-12);  // round-off of ~1500 terms; measured 2.6e-13 m
  }
  // the record repeats with period D
  CHECK(field.elevation(3.0, 4.0, 17.3 + p.duration_s) == Approx(field.elevation(3.0, 4.0, 17.3)).margin(1e-11));
}

TEST_CASE("cut-off frequencies drop components and keep the others' phases", "[unit][waves]") {
  WaveParams p = jonswap(3.0, 7.0, 2.0, 60.0, 600.0, 0.2, 5);
  const WaveField all(p);
  p.cutoff_low_hz = 0.08;
  p.cutoff_high_hz = 0.4;
  const WaveField band(p);
  REQUIRE_FALSE(band.components().empty());
  CHECK(band.components().front().omega_rad_s >= 2 * kPi * 0.08 * (1 - 1e-12));
  CHECK(band.components().back().omega_rad_s <= 2 * kPi * 0.4 * (1 + 1e-12));
  for (const WaveComponent& w : band.components()) {
    const auto it = std::find_if(all.components().begin(), all.components().end(),
                                 [&](const WaveComponent& v) { return v.harmonic == w.harmonic; });
    REQUIRE(it != all.components().end());
    CHECK(it->amplitude_m == w.amplitude_m);
  }
  CHECK(band.expected_m0_m2() < all.expected_m0_m2());
  // without cut-offs everything up to Nyquist is kept: N = 3000 → harmonics 1 … 1499
  CHECK(all.components().back().harmonic <= 1499);
}

TEST_CASE("synthesis is deterministic: same seed bit-identical, other seeds differ", "[unit][waves]") {
  const WaveParams p = jonswap(6.0, 10.0, 3.3, 320.0, 3600.0, 0.25, 42);
  const WaveField a(p), b(p);
  const std::vector<double> ea = a.elevation_series(5.0, 1.0), eb = b.elevation_series(5.0, 1.0);
  REQUIRE(ea.size() == eb.size());
  CHECK(std::memcmp(ea.data(), eb.data(), ea.size() * sizeof(double)) == 0);
  const WaveKinematics ka = a.evaluate(Vec3(1, 2, -3), 12.5), kb = b.evaluate(Vec3(1, 2, -3), 12.5);
  CHECK(std::memcmp(ka.velocity_m_s.data(), kb.velocity_m_s.data(), 3 * sizeof(double)) == 0);
  const std::vector<Vec3> points{{0, 0, -3}, {0, 0, -30}};
  const PrecomputedKinematics pa(a, points), pb(b, points);
  for (double t : {0.0, 1.3, 777.7}) {
    const WaveKinematics x = pa.at(1, t), y = pb.at(1, t);
    CHECK(std::memcmp(x.acceleration_m_s2.data(), y.acceleration_m_s2.data(), 3 * sizeof(double)) == 0);
    CHECK(std::memcmp(&x.dynamic_pressure_Pa, &y.dynamic_pressure_Pa, sizeof(double)) == 0);
  }
  WaveParams q = p;
  q.seed = 43;
  const std::vector<double> ec = WaveField(q).elevation_series(5.0, 1.0);
  std::size_t same = 0;
  for (std::size_t j = 0; j < ea.size(); ++j) same += ea[j] == ec[j];
  CHECK(same < ea.size() / 100);
  // Rayleigh amplitudes: same phases as deterministic ones (same draws), different amplitudes
  WaveParams r = p;
  r.rayleigh_amplitudes = true;
  const WaveField ray(r);
  REQUIRE(ray.components().size() == a.components().size());
  CHECK(std::arg(ray.components()[100].amplitude_m) == Approx(std::arg(a.components()[100].amplitude_m)));
  CHECK(std::abs(ray.components()[100].amplitude_m) != std::abs(a.components()[100].amplitude_m));
}

TEST_CASE("the random stream is mt19937_64 with our own uniform conversion", "[unit][waves]") {
  // The first harmonic's phase is 2π u with u = (⌊x/2¹¹⌋ + ½) 2⁻⁵³ from the first draw x of
  // std::mt19937_64(seed) — fixed by the C++ standard, so decks replay on any conforming library.
  // Two draws per harmonic (phase, amplitude) from harmonic 1 on, kept or not.
  const WaveParams p = jonswap(6.0, 10.0, 3.3, 320.0, 3600.0, 0.25, 2024);
  const WaveField field(p);
  const WaveComponent& first = field.components()[0];  // lowest harmonic with S > 0
  std::mt19937_64 rng(2024);
  rng.discard(2 * (first.harmonic - 1));
  const double u = (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53;
  const double expected_phase = 2.0 * kPi * u;
  CHECK(std::remainder(std::arg(first.amplitude_m) - expected_phase, 2.0 * kPi) == Approx(0.0).margin(1e-14));
}
