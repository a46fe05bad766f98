#include "fowtsim/wind/turbulence_generator.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/fft.hpp"
#include "fowtsim/wind/coherent_sampler.hpp"
#include "fowtsim/wind/iec_turbulence.hpp"
#include "fowtsim/wind/tower_sampler.hpp"

namespace fowtsim::wind {
namespace {

using Complex = std::complex<double>;

Complex random_phasor(std::mt19937_64& generator) {
  const double theta = 2.0 * std::numbers::pi * uniform01(generator);
  return {std::cos(theta), std::sin(theta)};
}

}  // namespace

GeneratedTurbulence generate_turbulence(const WindParams& params) {
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
  const std::size_t points = static_cast<std::size_t>(f.ny) * f.nz;
  f.grid.assign(static_cast<std::size_t>(n) * points * 3, 0.0f);
  f.n_tower = t.tower_points ? turbsim_tower_point_count(f.z_bottom_m, f.dz_m) : 0;
  f.tower.assign(static_cast<std::size_t>(n) * f.n_tower * 3, 0.0f);

  const int bins = n / 2 + 1;                        // c2r input length
  const int top = (n % 2 == 0) ? n / 2 - 1 : n / 2;  // last carried frequency index (no Nyquist)
  const double df = 1.0 / (n * t.dt_s);
  TurbulenceStats& stats = out.stats;
  stats.frequencies = top;

  std::mt19937_64 generator(t.seed);
  CoherentSampler sampler(f.ny, f.nz, f.dy_m, f.dz_m);
  std::vector<Complex> xi(std::max(sampler.embedding_size(), points));
  std::vector<Complex> x(points);
  std::vector<Complex> spectra(points * bins);  // [point][bin]
  // signal[t] = Σ_k Y_k e^{+i 2π k t / n} over the Hermitian-extended spectrum Y_0 … Y_{n/2}.
  InverseRealFft inverse(static_cast<std::size_t>(n));
  const auto inverse_dft = [&inverse, bins](const Complex* y) {
    std::copy(y, y + bins, inverse.coefficients());
    return inverse.execute();
  };
  // Tower points: their own stream, so that the grid's draws (hence values) do not change.
  std::mt19937_64 tower_generator(t.seed + 0x9E3779B97F4A7C15ULL);
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
    std::fill(spectra.begin(), spectra.end(), Complex(0.0, 0.0));
    std::fill(tower_spectra.begin(), tower_spectra.end(), Complex(0.0, 0.0));
    double variance = 0.0;
    for (int m = 1; m <= top; ++m) {
      const double fm = m * df;
      const double s = kaimal.spectrum(c, fm);
      variance += s * df;
      // c2r gives Y_0 + 2 Re Σ Y_m e^{iωt}: Y_m = sqrt(2 S Δf) X / 2.
      const double amplitude = std::sqrt(0.5 * s * df);
      for (std::size_t d = 0; d < tower_draws; ++d) eta[d] = random_phasor(tower_generator);
      if (c == 0) {
        const double a = kaimal.coherence_decay_per_m(fm);
        const CoherentSampler::Method method = sampler.prepare(a);
        switch (method) {
          case CoherentSampler::Method::independent: ++stats.independent_frequencies; break;
          case CoherentSampler::Method::embedding: ++stats.embedding_frequencies; break;
          case CoherentSampler::Method::dense: ++stats.dense_frequencies; break;
        }
        const std::size_t draws = sampler.draws();
        for (std::size_t k = 0; k < draws; ++k) xi[k] = random_phasor(generator);
        sampler.sample(std::span<const Complex>(xi.data(), draws), x);
        if (tower_draws > 0) {
          const bool grid_exact = method != CoherentSampler::Method::independent;
          if (tower.prepare(a, grid_exact) == TowerSampler::Method::conditional) ++stats.tower_conditional_frequencies;
          else ++stats.tower_independent_frequencies;
          tower.sample(x, eta, x_tower);
        }
      } else {
        for (std::size_t j = 0; j < points; ++j) x[j] = random_phasor(generator);
        std::copy(eta.begin(), eta.end(), x_tower.begin());  // v, w: no coherence between points
      }
      for (std::size_t j = 0; j < points; ++j) spectra[j * bins + m] = amplitude * x[j];
      for (std::size_t d = 0; d < tower_draws; ++d) tower_spectra[d * bins + m] = amplitude * x_tower[d];
    }
    stats.iec_sigma_m_s[c] = kaimal.component[c].sigma_m_s;
    stats.expected_sigma_m_s[c] = std::sqrt(variance);

    for (std::size_t j = 0; j < points; ++j) {
      const double* series = inverse_dft(&spectra[j * bins]);
      const double mean = (c == 0) ? mean_u[j / f.ny] : 0.0;
      for (int it = 0; it < n; ++it) {
        const double value = mean + series[it];
        f.grid[(static_cast<std::size_t>(it) * points + j) * 3 + c] = static_cast<float>(value);
      }
    }
    const std::size_t nw = static_cast<std::size_t>(f.n_tower);
    if (tower.first_on_grid())  // tower point 0 is the grid's bottom-centre point (TurbSim: the same point)
      for (int it = 0; it < n; ++it)
        f.tower[(static_cast<std::size_t>(it) * nw) * 3 + c] =
            f.grid[(static_cast<std::size_t>(it) * points + tower.first_grid_index()) * 3 + c];
    for (std::size_t d = 0; d < tower_draws; ++d) {
      const double* series = inverse_dft(&tower_spectra[d * bins]);
      const double mean = (c == 0) ? tower_mean_u[d] : 0.0;
      const std::size_t k = static_cast<std::size_t>(tower_first) + d;
      for (int it = 0; it < n; ++it)
        f.tower[(static_cast<std::size_t>(it) * nw + k) * 3 + c] = static_cast<float>(mean + series[it]);
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
