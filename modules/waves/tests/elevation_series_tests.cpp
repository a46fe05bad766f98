// Replaying a sea (model elevation_series, OpenFAST SeaState WaveMod 5): a synthetic record is
// sampled from a known sum of Airy components (a JONSWAP realisation of this module), the sea is
// rebuilt from the samples alone, and compared with the original — at the record point, downwave
// and at depth — plus the checks of a bad record.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/waves/waves_module.hpp"
#include "test_waves.hpp"

using namespace waves_test;
using fowtsim::InputError;

namespace {

struct Record {
  std::vector<double> t, eta;
};

// η of `field` at the origin at t₀ + j Δt, j < n, by direct summation (any t₀, not only grid times),
// plus a constant offset (a record whose mean is not zero, e.g. a gauge datum).
Record sample(const WaveField& field, double t0, double dt, std::size_t n, double offset_m = 0.0) {
  Record r;
  for (std::size_t j = 0; j < n; ++j) {
    const double t = t0 + static_cast<double>(j) * dt;
    r.t.push_back(t);
    r.eta.push_back(field.elevation(0.0, 0.0, t) + offset_m);
  }
  return r;
}

WaveParams replay(const WaveParams& original, const Record& r) {
  WaveParams base;
  base.heading_deg = original.heading_deg;
  base.depth_m = original.depth_m;
  base.stretching = original.stretching;
  return with_elevation_record(base, r.t, r.eta, "synthetic record");
}

std::string message_of(const WaveParams& p) {
  try {
    const WaveField field(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

double max_abs(const std::vector<double>& x) {
  double m = 0.0;
  for (double v : x) m = std::max(m, std::abs(v));
  return m;
}

// Horizontal particle velocity along the heading at p, and the elevation there.
struct Probe {
  double eta, u;
};
Probe probe(const WaveField& f, const Vec3& p, double t) {
  const WaveKinematics k = f.evaluate(p, t);
  return {k.elevation_m, k.velocity_m_s.dot(f.direction())};
}

}  // namespace

TEST_CASE("a sea rebuilt from one full period of its own record is the same sea", "[verification][waves]") {
  // Original: JONSWAP Hs 6 m, Tp 10 s, γ 3.3, 320 m, heading 30°, D = 1200 s, Δt = 0.25 s (4800
  // samples; 2375 components — JONSWAP is 0 in double below ~0.03 Hz). The record is one whole period
  // sampled at Δt from t₀ = 137.3 s (not a grid time, not zero) with a 0.4 m datum offset. Its DFT then
  // holds exactly the original components, so everything — not only η at the record point — must
  // agree to round-off.
  WaveParams original_p = jonswap(6.0, 10.0, 3.3, 320.0, 1200.0, 0.25, 7);
  original_p.heading_deg = 30.0;
  const WaveField original(original_p);
  const double t0 = 137.3, offset = 0.4;
  const Record r = sample(original, t0, 0.25, 4800, offset);
  const WaveField rebuilt(replay(original_p, r));

  CHECK(rebuilt.record_samples() == 4800);
  CHECK(rebuilt.record_duration_s() == Approx(1200.0).epsilon(1e-14));
  CHECK(rebuilt.removed_mean_m() == Approx(offset).epsilon(1e-12));
  // Same components: the original's harmonics (those where JONSWAP is not 0 in double) with the same
  // A_n (measured |ΔA| ≤ 5.4e-14 m); the others, and the Nyquist bin, at round-off (2.8e-15 m).
  // Bounds 1e-13 m: the DFT's round-off, ~ eps √N max|η|.
  double stray = 0.0, amplitude_error = 0.0;
  std::size_t matched = 0;
  for (const WaveComponent& w : rebuilt.components()) {
    const auto o = std::find_if(original.components().begin(), original.components().end(),
                                [&](const WaveComponent& c) { return c.harmonic == w.harmonic; });
    if (o == original.components().end()) {
      stray = std::max(stray, std::abs(w.amplitude_m));
    } else {
      ++matched;
      amplitude_error = std::max(amplitude_error, std::abs(w.amplitude_m - o->amplitude_m));
      CHECK(w.wavenumber_rad_m == o->wavenumber_rad_m);
    }
  }
  INFO("full period: max |dA| " << amplitude_error << " m, stray " << stray << " m");
  CHECK(matched == original.components().size());
  CHECK(amplitude_error < 1e-13);
  CHECK(stray < 1e-13);

  // (a) the record point reproduces the record (minus its mean) at the sample times.
  const double scale = max_abs(r.eta);
  double err_a = 0.0;
  for (std::size_t j = 0; j < r.t.size(); ++j)
    err_a = std::max(err_a, std::abs(rebuilt.elevation(0.0, 0.0, r.t[j]) - (r.eta[j] - offset)));
  INFO("full period: record point max error " << err_a << " m (" << err_a / scale << " of max |eta|)");
  // Round-off of a 4800-point DFT and a 2400-term sum at phases ω t up to 2e4 rad: measured 9.5e-13 m
  // (1.7e-13 of max |η|); bound 1e-11 m.
  CHECK(err_a < 1e-11);

  // (b) 50 m downwave: η at the surface and the horizontal velocity at z = −20 m, at times inside,
  // before and after the record (the rebuilt sea repeats with D, as the original does).
  const Vec3 e = original.direction();
  const Vec3 surface = 50.0 * e, deep = 50.0 * e + Vec3(0.0, 0.0, -20.0);
  double err_eta = 0.0, err_u = 0.0, max_eta = 0.0, max_u = 0.0;
  for (double t = -300.0; t < 2700.0; t += 1.37) {
    const Probe o = probe(original, surface, t), b = probe(rebuilt, surface, t);
    const Probe od = probe(original, deep, t), bd = probe(rebuilt, deep, t);
    err_eta = std::max(err_eta, std::abs(o.eta - b.eta));
    err_u = std::max(err_u, std::abs(od.u - bd.u));
    max_eta = std::max(max_eta, std::abs(o.eta));
    max_u = std::max(max_u, std::abs(od.u));
  }
  INFO("full period: 50 m downwave max error eta " << err_eta << " m (max " << max_eta << "), u(-20 m) " << err_u
                                                     << " m/s (max " << max_u << ")");
  // Same components ⇒ same sea everywhere: round-off only. Measured 7.8e-13 m and 1.4e-13 m/s;
  // bounds ≈ 10×: 1e-11 m, 2e-12 m/s.
  CHECK(err_eta < 1e-11);
  CHECK(err_u < 2e-12);
}

TEST_CASE("a sea rebuilt from a 600-s window of a longer sea", "[verification][waves]") {
  // The realistic case: the record is a window (600 s from t₀ = 2000 s) of a sea whose period is
  // 3600 s, so the window is not periodic. The rebuilt sea reproduces the record (minus its mean) at
  // the record point exactly (a), but its components sit on the 1/600 Hz grid instead of 1/3600 Hz:
  // each original component is spread over neighbouring bins (leakage) that travel with slightly
  // different wavenumbers, and the periodic splice of the window's ends travels downwave. (b) then
  // measures how far from the original sea the replay is 50 m downwave, in the middle of the window.
  const WaveParams original_p = jonswap(6.0, 10.0, 3.3, 320.0, 3600.0, 0.25, 3);
  const WaveField original(original_p);
  const double t0 = 2000.0, dt = 0.25;
  const Record r = sample(original, t0, dt, 2400);
  const WaveField rebuilt(replay(original_p, r));
  CHECK(rebuilt.record_duration_s() == Approx(600.0).epsilon(1e-14));
  const double mean = rebuilt.removed_mean_m();

  // (a) record point, at the sample times: round-off (measured 2.1e-12 m, 5.5e-13 m; bound 1e-11 m), by
  // summation and through the module's precomputed Wave1Elev (t₀ and Δt on its grid).
  double err_a = 0.0;
  for (std::size_t j = 0; j < r.t.size(); ++j)
    err_a = std::max(err_a, std::abs(rebuilt.elevation(0.0, 0.0, r.t[j]) - (r.eta[j] - mean)));
  const Waves::Params module = Waves::make_params(replay(original_p, r));
  double err_module = 0.0;
  for (std::size_t j = 0; j < r.t.size(); ++j)
    err_module = std::max(err_module,
                          std::abs(Waves::outputs(module, {}, Waves::State{r.t[j]}).elevation_m[0] - (r.eta[j] - mean)));
  INFO("window: mean " << mean << " m; record point max error " << err_a << " m, Wave1Elev " << err_module << " m");
  CHECK(err_a < 1e-11);
  CHECK(err_module < 1e-11);

  // (b) 50 m downwave, t ∈ [t₀ + 60 s, t₀ + 540 s]: away from the splice by more than the time waves
  // of the energetic band take to travel 50 m (group velocity gT/4π ≈ 5.5 … 11 m/s for T = 7 … 14 s).
  struct Errors {
    double rel_eta, max_eta, rel_u, max_u;  // RMS error / RMS signal; max |error| / RMS signal
  };
  const auto downwave = [&](const WaveField& replayed) {
    const Vec3 surface(50.0, 0.0, 0.0), deep(50.0, 0.0, -20.0);
    double se = 0.0, su = 0.0, ve = 0.0, vu = 0.0, me = 0.0, mu = 0.0;
    double count = 0.0;
    for (double t = t0 + 60.0; t <= t0 + 540.0; t += 0.35, count += 1.0) {
      const Probe o = probe(original, surface, t), b = probe(replayed, surface, t);
      const Probe od = probe(original, deep, t), bd = probe(replayed, deep, t);
      se += (o.eta - b.eta) * (o.eta - b.eta), ve += o.eta * o.eta;
      su += (od.u - bd.u) * (od.u - bd.u), vu += od.u * od.u;
      me = std::max(me, std::abs(o.eta - b.eta)), mu = std::max(mu, std::abs(od.u - bd.u));
    }
    return Errors{std::sqrt(se / ve), me / std::sqrt(ve / count), std::sqrt(su / vu), mu / std::sqrt(vu / count)};
  };
  const Errors all = downwave(rebuilt);
  INFO("window, no cut-off: 50 m downwave eta RMS error " << all.rel_eta << ", max " << all.max_eta
       << "; u(-20 m) RMS error " << all.rel_u << ", max " << all.max_u << " (of the RMS signals)");
  // Measured (of the RMS signals 1.51 m, 0.371 m/s): η 1.09e-2 RMS, 6.0e-2 max — leakage: an original
  // component between two 1/600-Hz bins is carried by bins whose k differs by ~Δω/c_g, a phase error
  // of a few 0.01 rad over 50 m. u 1.47e-3 RMS and max: a steady 5.5e-4 m/s = mean √(g/h): with the
  // window's mean (3.1 mm) removed, the lowest harmonics hold −mean inside the window, a long wave
  // whose current is η √(g/h). Bounds ≈ 10× above, rounded: 0.1, 0.5; 0.015, 0.015.
  CHECK(all.rel_eta < 0.1);
  CHECK(all.max_eta < 0.5);
  CHECK(all.rel_u < 0.015);
  CHECK(all.max_u < 0.015);

  // cutoff_low_hz = 0.03 Hz (JONSWAP Tp 10 s has no energy there) removes that current, but also the
  // part of the band's leakage carried by those bins: measured η 1.09e-2 RMS, 6.1e-2 max; u 2.0e-3
  // RMS, 5.9e-3 max — no better. A low cut-off is for records with real low-frequency noise (drift
  // of a gauge), not a cure for leakage. Bounds ≈ 10×: 0.1, 0.5; 0.02, 0.06.
  WaveParams cut = replay(original_p, r);
  cut.cutoff_low_hz = 0.03;
  const Errors band = downwave(WaveField(cut));
  INFO("window, cutoff_low_hz 0.03: 50 m downwave eta RMS error " << band.rel_eta << ", max " << band.max_eta
       << "; u(-20 m) RMS error " << band.rel_u << ", max " << band.max_u << " (of the RMS signals)");
  CHECK(band.rel_eta < 0.1);
  CHECK(band.max_eta < 0.5);
  CHECK(band.rel_u < 0.02);
  CHECK(band.max_u < 0.06);
}

TEST_CASE("elevation_series: cut-offs, repetition, module probes, determinism", "[unit][waves]") {
  const WaveParams original_p = jonswap(2.0, 8.0, 3.3, 200.0, 600.0, 0.5, 11);
  const WaveField original(original_p);
  const Record r = sample(original, 0.0, 0.5, 1200);
  WaveParams p = replay(original_p, r);

  // The record repeats with its length D = N Δt: a simulation longer than the record sees it again.
  const WaveField rebuilt(p);
  for (std::size_t j = 0; j < r.t.size(); j += 97)
    CHECK(rebuilt.elevation(0.0, 0.0, r.t[j] + 2.0 * 600.0) == Approx(r.eta[j]).margin(1e-11));

  // Cut-offs keep the components inside [low, high] unchanged and drop the others.
  p.cutoff_low_hz = 0.05;
  p.cutoff_high_hz = 0.2;
  const WaveField band(p);
  REQUIRE(!band.calm());
  CHECK(band.components().front().omega_rad_s >= 2 * kPi * 0.05);
  CHECK(band.components().back().omega_rad_s <= 2 * kPi * 0.2 * (1 + 1e-12));
  for (const WaveComponent& w : band.components()) {
    const WaveComponent& full = rebuilt.components()[w.harmonic - rebuilt.components().front().harmonic];
    CHECK(full.harmonic == w.harmonic);
    CHECK(full.amplitude_m == w.amplitude_m);
  }

  // The module contract works unchanged: Wave1Elev at the origin reproduces the record (t₀ = 0 puts
  // the samples on the precomputed grid, so the lookup is exact there).
  const Waves::Params module = Waves::make_params(replay(original_p, r));
  for (std::size_t j = 0; j < r.t.size(); j += 31)
    CHECK(Waves::outputs(module, {}, Waves::State{r.t[j]}).elevation_m[0] == Approx(r.eta[j]).margin(1e-11));

  // Bit-identical rebuilds (FFTW_ESTIMATE plans).
  const WaveField again(replay(original_p, r));
  REQUIRE(again.components().size() == rebuilt.components().size());
  for (std::size_t i = 0; i < again.components().size(); ++i)
    CHECK(again.components()[i].amplitude_m == rebuilt.components()[i].amplitude_m);

  // A constant record is calm. A pure Nyquist record (−1)^j is kept (cos π(t − t₀)/Δt) and comes out
  // of the summation, the FFT series and the precomputed lookups (oversampling 1, where c2r holds the
  // Nyquist coefficient once) alike.
  std::vector<double> t(16), constant(16, 1.5), nyquist(16);
  for (std::size_t j = 0; j < 16; ++j) t[j] = 0.5 * j, nyquist[j] = j % 2 ? -1.0 : 1.0;
  CHECK(WaveField(with_elevation_record({}, t, constant)).calm());
  CHECK(WaveField(with_elevation_record({}, t, constant)).removed_mean_m() == Approx(1.5));
  const WaveField nyq(with_elevation_record({}, t, nyquist));
  REQUIRE(nyq.components().size() == 1);
  const std::vector<double> series = nyq.elevation_series(0.0, 0.0, 1);
  PrecomputeOptions once;
  once.oversampling = 1;
  const std::vector<Vec3> origin{Vec3(0.0, 0.0, 0.0)};
  const PrecomputedKinematics looked_up(nyq, origin, once);
  for (std::size_t j = 0; j < 16; ++j) {
    CHECK(nyq.elevation(0.0, 0.0, t[j]) == Approx(nyquist[j]).margin(1e-13));
    CHECK(series[j] == Approx(nyquist[j]).margin(1e-13));
    CHECK(looked_up.elevation(0, t[j]) == Approx(nyquist[j]).margin(1e-13));
  }
}

TEST_CASE("elevation_series: a bad record is an InputError naming file, line and what was expected",
          "[unit][waves]") {
  std::vector<double> t, eta;
  for (int j = 0; j < 20; ++j) t.push_back(10.0 + 0.25 * j), eta.push_back(std::sin(0.3 * j));
  const auto params = [](std::vector<double> tt, std::vector<double> ee) {
    ElevationRecord r = make_elevation_record(tt, ee, "sea.txt");
    for (std::size_t j = 0; j < r.time_s.size(); ++j) r.lines.push_back(j + 3);  // two header lines
    WaveParams p;
    p.model = WaveModel::elevation_series;
    p.elevation_record = std::make_shared<const ElevationRecord>(r);
    return p;
  };
  CHECK(message_of(params(t, eta)).empty());

  // Non-uniform: sample 7 (line 10) 0.1 s late; a missing sample; times going back.
  std::vector<double> late = t;
  late[7] += 0.1;
  std::string m = message_of(params(late, eta));
  CHECK(m.find("sea.txt:10") != std::string::npos);
  CHECK(m.find("expected uniform sampling") != std::string::npos);
  std::vector<double> gap_t = t, gap_eta = eta;
  gap_t.erase(gap_t.begin() + 12), gap_eta.erase(gap_eta.begin() + 12);
  CHECK(message_of(params(gap_t, gap_eta)).find("expected uniform sampling") != std::string::npos);
  std::vector<double> reversed(t.rbegin(), t.rend());
  CHECK(message_of(params(reversed, eta)).find("times must increase") != std::string::npos);
  // Printed-time rounding (0.1 % of a step) passes.
  std::vector<double> rounded = t;
  rounded[5] += 0.00025;
  CHECK(message_of(params(rounded, eta)).empty());

  // Too few samples: 0, 1, and 7 (< 8, the floor of every record).
  for (std::size_t n : {0, 1, 7}) {
    const std::string msg =
        message_of(params(std::vector<double>(t.begin(), t.begin() + n), std::vector<double>(eta.begin(), eta.begin() + n)));
    INFO(msg);
    CHECK(msg.find("at least 8 samples") != std::string::npos);
  }

  // NaN / infinite values, named with their line.
  std::vector<double> bad_eta = eta;
  bad_eta[4] = std::nan("");
  m = message_of(params(t, bad_eta));
  CHECK(m.find("sea.txt:7") != std::string::npos);
  CHECK(m.find("elevation is nan") != std::string::npos);
  std::vector<double> bad_t = t;
  bad_t[0] = std::numeric_limits<double>::infinity();
  CHECK(message_of(params(bad_t, eta)).find("sea.txt:3: time is inf") != std::string::npos);

  // Lengths differ; no record at all; cut-off above the record's Nyquist (2 Hz).
  CHECK(message_of(params(t, std::vector<double>(eta.begin(), eta.end() - 1))).find("20 times but 19 elevations") !=
        std::string::npos);
  WaveParams none;
  none.model = WaveModel::elevation_series;
  CHECK(message_of(none).find("needs an elevation record") != std::string::npos);
  WaveParams high = params(t, eta);
  high.cutoff_high_hz = 2.5;
  CHECK(message_of(high).find("Nyquist") != std::string::npos);
  // Without line numbers the sample index is named.
  CHECK(message_of(with_elevation_record({}, late, eta, "memory")).find("memory: sample 7") != std::string::npos);
}
