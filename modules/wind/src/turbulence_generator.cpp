#include "fowtsim/wind/turbulence_generator.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <complex>
#include <numbers>
#include <span>
#include <vector>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/fft.hpp"
#include "fowtsim/wind/coherent_sampler.hpp"
#include "fowtsim/wind/iec_turbulence.hpp"
#include "fowtsim/wind/tower_sampler.hpp"

namespace fowtsim::wind {
namespace {
using Complex = std::complex<double>;
}  // namespace

// How: the quadrant q = round(k / 2⁵¹) and the remainder k − q 2⁵¹ ∈ [−2⁵⁰, 2⁵⁰] are exact
// integers, x = (k − q 2⁵¹)·(π/2)·2⁻⁵¹ ∈ [−π/4, π/4] carries one rounding, the Taylor series to
// x¹⁷ (sin) and x¹⁸ (cos) truncate below 1e-19 there, and θ = q π/2 + x selects and negates
// exactly. Branch-free (the quadrant is random) and free of calls, so the second loop vectorises.
void fill_random_phasors(MersenneTwister64& generator, Complex* out, std::size_t count) {
  constexpr std::size_t kBatch = 256;
  constexpr double kScale = 0.5 * std::numbers::pi * 0x1.0p-51;  // (π/2)·2⁻⁵¹
  // 1/n! for n = 2 … 18.
  constexpr double f2 = 1.0 / 2, f3 = f2 / 3, f4 = f3 / 4, f5 = f4 / 5, f6 = f5 / 6, f7 = f6 / 7, f8 = f7 / 8,
                   f9 = f8 / 9, f10 = f9 / 10, f11 = f10 / 11, f12 = f11 / 12, f13 = f12 / 13, f14 = f13 / 14,
                   f15 = f14 / 15, f16 = f15 / 16, f17 = f16 / 17, f18 = f17 / 18;
  double x_batch[kBatch];          // x ∈ [−π/4, π/4] [rad]
  std::uint64_t quadrant[kBatch];  // q ∈ 0 … 4 (4 ≡ 0)
  double* o = reinterpret_cast<double*>(out);  // std::complex<double> is an array of two doubles
  for (std::size_t start = 0; start < count; start += kBatch) {
    const std::size_t m = std::min(kBatch, count - start);
    for (std::size_t i = 0; i < m; ++i) {
      const std::uint64_t k = generator() >> 11;
      const std::uint64_t q = (k + (std::uint64_t{1} << 50)) >> 51;
      x_batch[i] = static_cast<double>(static_cast<std::int64_t>(k) - static_cast<std::int64_t>(q << 51)) * kScale;
      quadrant[i] = q;
    }
    for (std::size_t i = 0; i < m; ++i) {
      const double x = x_batch[i], x2 = x * x;
      const std::uint64_t q = quadrant[i];
      const double s =
          x + x * x2 * (-f3 + x2 * (f5 + x2 * (-f7 + x2 * (f9 + x2 * (-f11 + x2 * (f13 + x2 * (-f15 + x2 * f17)))))));
      const double c =
          1.0 + x2 * (-f2 + x2 * (f4 + x2 * (-f6 + x2 * (f8 + x2 * (-f10 + x2 * (f12 + x2 * (-f14 + x2 * (f16 - x2 * f18))))))));
      // θ = q π/2 + x: q = 0 (c, s), 1 (−s, c), 2 (−c, −s), 3 (s, −c); selected and negated by bits.
      const std::uint64_t odd = std::uint64_t{0} - (q & 1);  // all ones when q is odd
      const std::uint64_t bits_s = std::bit_cast<std::uint64_t>(s), bits_c = std::bit_cast<std::uint64_t>(c);
      const std::uint64_t a = (bits_s & odd) | (bits_c & ~odd), b = (bits_c & odd) | (bits_s & ~odd);
      o[2 * (start + i)] = std::bit_cast<double>(a ^ (((q + 1) & 2) << 62));
      o[2 * (start + i) + 1] = std::bit_cast<double>(b ^ ((q & 2) << 62));
    }
  }
}

GeneratedTurbulence generate_turbulence(const WindParams& params, std::optional<HeldTimes> held_times) {
  validate(params);
  if (params.model != WindModel::turbulent)
    throw InputError(ErrorContext{"wind.turbulence", std::nullopt, "wind.model", ""},
                     "generate_turbulence needs wind.model = turbulent");
  const TurbulenceParams& t = params.turbulence;
  const double v_hub = params.speed_m_s;
  const double z_hub = params.reference_height_m;
  const KaimalModel kaimal = kaimal_model(t, v_hub, z_hub);

  GeneratedTurbulence out;
  FullField& f = out.field;
  f.ny = t.ny;
  f.nz = t.nz;
  f.n_tower = 0;  // set below, once the grid's geometry is known
  f.nt = static_cast<int>(std::llround(t.duration_s / t.dt_s));
  f.dy_m = t.width_m / (t.ny - 1);
  f.dz_m = t.height_m / (t.nz - 1);
  f.dt_s = t.dt_s;
  f.z_hub_m = z_hub;
  f.z_bottom_m = z_hub - 0.5 * t.height_m;
  f.u_hub_m_s = v_hub;
  f.periodic = true;
  const int n = f.nt;
  // Samples held: up to `until_s` and from `before_start_s` before the end, each with the next
  // sample that brackets it.
  if (held_times && held_times->until_s >= 0.0 && held_times->before_start_s >= 0.0) {
    const double head = std::ceil(held_times->until_s / t.dt_s) + 2.0;
    const double tail = std::ceil(held_times->before_start_s / t.dt_s) + 2.0;
    if (head + tail < n) {
      f.nt_held = static_cast<int>(head);
      f.nt_tail = static_cast<int>(tail);
    }
  }
  const int held = f.held_steps();
  // Record sample of held row r.
  const auto record_row = [&f, n](int r) { return (f.nt_held == 0 || r < f.nt_held) ? r : n - f.nt_tail + (r - f.nt_held); };
  const std::size_t points = static_cast<std::size_t>(f.ny) * f.nz;
  f.grid.assign(static_cast<std::size_t>(held) * points * 3, 0.0f);
  f.n_tower = t.tower_points ? turbsim_tower_point_count(f.z_bottom_m, f.dz_m) : 0;
  f.tower.assign(static_cast<std::size_t>(held) * f.n_tower * 3, 0.0f);

  const int bins = n / 2 + 1;                        // c2r input length
  const int top = (n % 2 == 0) ? n / 2 - 1 : n / 2;  // last carried frequency index (no Nyquist)
  const double df = 1.0 / (n * t.dt_s);
  TurbulenceStats& stats = out.stats;
  stats.frequencies = top;

  MersenneTwister64 generator(t.seed);  // the stream of std::mt19937_64(seed)
  CoherentSampler sampler(f.ny, f.nz, f.dy_m, f.dz_m);
  std::vector<Complex> xi(std::max(sampler.embedding_size(), points));
  // Frequencies are drawn in blocks of kFrequencyBlock ([frequency][point]) and written into the
  // point-major spectra one block at a time; the series of kPointBlock points are converted into
  // one buffer ([point][time]) and written into the time-major grid one block at a time. Column
  // by column, these two transposes were 27 % of the default deck's set-up (issue 28): every
  // write touched another cache line and page.
  constexpr int kFrequencyBlock = 16;
  constexpr std::size_t kPointBlock = 32;
  std::vector<Complex> x_block(points * kFrequencyBlock);
  double amplitudes[kFrequencyBlock];
  std::vector<float> series_block(kPointBlock * static_cast<std::size_t>(held));
  std::vector<Complex> spectra(points * bins);  // [point][bin]; bins 0 and past `top` stay zero
  // signal[t] = Σ_k Y_k e^{+i 2π k t / n} over the Hermitian-extended spectrum Y_0 … Y_{n/2}.
  InverseRealFft inverse(static_cast<std::size_t>(n));
  const auto inverse_dft = [&inverse, bins](const Complex* y) {
    std::copy(y, y + bins, inverse.coefficients());
    return inverse.execute();
  };
  // Tower points: their own stream, so that the grid's draws (hence values) do not change.
  MersenneTwister64 tower_generator(t.seed + 0x9E3779B97F4A7C15ULL);
  TowerSampler tower(f.ny, f.nz, f.dy_m, f.dz_m, f.n_tower);
  const std::size_t tower_draws = tower.draws();
  const int tower_first = tower.first_on_grid() ? 1 : 0;  // index of the first drawn tower point
  std::vector<Complex> eta(tower_draws), x_tower(tower_draws);
  std::vector<Complex> tower_spectra(tower_draws * bins);
  std::vector<double> tower_mean_u(tower_draws);
  for (std::size_t d = 0; d < tower_draws; ++d)
    tower_mean_u[d] = v_hub * std::pow((f.z_bottom_m - (tower_first + static_cast<int>(d)) * f.dz_m) / z_hub,
                                       params.shear_exponent);

  std::vector<double> mean_u(f.nz);  // power-law profile U(z) = V_hub (z / z_hub)^alpha
  for (int iz = 0; iz < f.nz; ++iz)
    mean_u[iz] = v_hub * std::pow((f.z_bottom_m + iz * f.dz_m) / z_hub, params.shear_exponent);

  for (int c = 0; c < 3; ++c) {
    double variance = 0.0;
    for (int m0 = 1; m0 <= top; m0 += kFrequencyBlock) {
      const int block = std::min(kFrequencyBlock, top - m0 + 1);
      for (int b = 0; b < block; ++b) {
        const int m = m0 + b;
        const double fm = m * df;
        const double s = kaimal.spectrum(c, fm);
        variance += s * df;
        // c2r gives Y_0 + 2 Re Σ Y_m e^{iωt}: Y_m = sqrt(2 S Δf) X / 2.
        const double amplitude = std::sqrt(0.5 * s * df);
        amplitudes[b] = amplitude;
        const std::span<Complex> x(&x_block[static_cast<std::size_t>(b) * points], points);
        fill_random_phasors(tower_generator, eta.data(), tower_draws);
        if (c == 0) {
          const double a = kaimal.coherence_decay_per_m(fm);
          const CoherentSampler::Method method = sampler.prepare(a);
          switch (method) {
            case CoherentSampler::Method::independent: ++stats.independent_frequencies; break;
            case CoherentSampler::Method::embedding: ++stats.embedding_frequencies; break;
            case CoherentSampler::Method::dense: ++stats.dense_frequencies; break;
          }
          const std::size_t draws = sampler.draws();
          fill_random_phasors(generator, xi.data(), draws);
          sampler.sample(std::span<const Complex>(xi.data(), draws), x);
          if (tower_draws > 0) {
            const bool grid_exact = method != CoherentSampler::Method::independent;
            if (tower.prepare(a, grid_exact) == TowerSampler::Method::conditional) ++stats.tower_conditional_frequencies;
            else ++stats.tower_independent_frequencies;
            tower.sample(x, eta, x_tower);
          }
        } else {
          fill_random_phasors(generator, x.data(), points);
          std::copy(eta.begin(), eta.end(), x_tower.begin());  // v, w: no coherence between points
        }
        for (std::size_t d = 0; d < tower_draws; ++d) tower_spectra[d * bins + m] = amplitude * x_tower[d];
      }
      for (std::size_t j = 0; j < points; ++j) {
        Complex* y = &spectra[j * bins + m0];
        for (int b = 0; b < block; ++b) y[b] = amplitudes[b] * x_block[static_cast<std::size_t>(b) * points + j];
      }
    }
    stats.iec_sigma_m_s[c] = kaimal.component[c].sigma_m_s;
    stats.expected_sigma_m_s[c] = std::sqrt(variance);

    for (std::size_t j0 = 0; j0 < points; j0 += kPointBlock) {
      const std::size_t block = std::min(kPointBlock, points - j0);
      for (std::size_t b = 0; b < block; ++b) {
        const std::size_t j = j0 + b;
        const double* series = inverse_dft(&spectra[j * bins]);
        const double mean = (c == 0) ? mean_u[j / f.ny] : 0.0;
        float* out_series = &series_block[b * static_cast<std::size_t>(held)];
        for (int r = 0; r < held; ++r) {
          const double value = mean + series[record_row(r)];
          out_series[r] = static_cast<float>(value);
        }
      }
      for (int it = 0; it < held; ++it) {
        float* row = &f.grid[(static_cast<std::size_t>(it) * points + j0) * 3 + c];
        for (std::size_t b = 0; b < block; ++b) row[3 * b] = series_block[b * static_cast<std::size_t>(held) + it];
      }
    }
    const std::size_t nw = static_cast<std::size_t>(f.n_tower);
    if (tower.first_on_grid())  // tower point 0 is the grid's bottom-centre point (TurbSim: the same point)
      for (int it = 0; it < held; ++it)
        f.tower[(static_cast<std::size_t>(it) * nw) * 3 + c] =
            f.grid[(static_cast<std::size_t>(it) * points + tower.first_grid_index()) * 3 + c];
    for (std::size_t d = 0; d < tower_draws; ++d) {
      const double* series = inverse_dft(&tower_spectra[d * bins]);
      const double mean = (c == 0) ? tower_mean_u[d] : 0.0;
      const std::size_t k = static_cast<std::size_t>(tower_first) + d;
      for (int r = 0; r < held; ++r)
        f.tower[(static_cast<std::size_t>(r) * nw + k) * 3 + c] = static_cast<float>(mean + series[record_row(r)]);
    }
  }
  stats.max_dropped_coherence = std::max(sampler.max_dropped_coherence(), tower.max_dropped_coherence());
  for (float v : f.tower)
    if (!std::isfinite(v))
      throw NumericalError(ErrorContext{"wind.turbulence", std::nullopt, "generated tower points", "check the inputs"},
                           "non-finite value in the generated tower points");
  for (float v : f.grid)
    if (!std::isfinite(v))
      throw NumericalError(ErrorContext{"wind.turbulence", std::nullopt, "generated field", "check the inputs"},
                           "non-finite value in the generated turbulence field");
  return out;
}

}  // namespace fowtsim::wind
