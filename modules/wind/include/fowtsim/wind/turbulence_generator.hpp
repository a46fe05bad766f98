#pragma once
// Our turbulence generator: IEC 61400-1 ed. 3 Kaimal spectra for u, v, w (Annex B, eq. B.1), the
// IEC exponential coherence for u (eq. B.2), v and w uncorrelated between points (as TurbSim's IEC
// Kaimal model), NTM or ETM sigma (§6.3.1.3, §6.3.2.3), power-law mean profile, by Veers' method
// (Veers 1988, SAND88-0152): per frequency, correlated unit-phasor amplitudes (CoherentSampler),
// then one real inverse FFT per point and component (FFTW, c2r).
//
//   u_j(t) = U(z_j) + Re Σ_m sqrt(2 S_u(f_m) Δf) X_j(f_m) e^{i 2π f_m t},  f_m = m / T, m = 1..⌈N/2⌉−1
//
// with T = duration, N = T/dt samples, E|X_j|² = 1 and E[X_j X_k*] = Coh_u(r_jk, f_m); the field is
// periodic with period T (stored as a periodic full field, TurbSim format id 8). The mean (m = 0) and
// the Nyquist term are zero, so the expected variance is Σ_m S(f_m) Δf, slightly below sigma² of the
// continuous spectrum (TurbStats::expected_sigma_m_s vs iec_sigma_m_s).
//
// Random numbers: std::mt19937_64(seed) (drawn through MersenneTwister64, the same stream); a phase is θ = 2π (g() >> 11)·2⁻⁵³ (our own uniform
// conversion) and its phasor (cos θ, sin θ) our own polynomial (fill_random_phasors), so the draws
// do not depend on the libm (the coherences and spectra still call exp, pow, hypot). Draw order:
// component u, v, w; frequency m ascending; then the sampler's draws (u) or points j ascending (v, w).
//
// Tower points (TurbulenceParams::tower_points, default on): TurbSim's column below the grid at y = 0
// (TowerSampler: layout, and u drawn jointly with the grid, conditionally on it, exact second
// moments), the same Kaimal spectra and mean profile U(z) at their heights, v and w independent. Their
// phasors come from a second stream std::mt19937_64(seed + 0x9E3779B97F4A7C15) in the same order, so
// the grid is bit-identical with and without tower points.
#include <complex>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>

#include "fowtsim/wind/full_field.hpp"
#include "fowtsim/wind/mersenne_twister.hpp"
#include "fowtsim/wind/params.hpp"

namespace fowtsim::wind {

// Uniform double in [0, 1) from the top 53 bits of one 64-bit draw.
inline double uniform01(std::mt19937_64& generator) {
  return static_cast<double>(generator() >> 11) * 0x1.0p-53;
}

// out[0 … count) = the unit phasors (cos θ, sin θ) of the next `count` draws of `generator`, in
// draw order, θ = 2π·uniform01(generator) (the same draws, the same θ). Computed without libm and
// more accurately than std::cos/std::sin of θ rounded to a double (whose argument error is up to
// 7e-16 near 2π): the two differ by at most 7.2e-16 over the first 40 M draws of seed 13428
// (1.1e-15 at the last representable θ), and the OC3 field (31×31, 630 s) came out
// float-for-float identical. 2.3× faster than libm's sincos with the draw (8 ns against 27 ns a
// phasor on this machine kind, issue 28). Allocates nothing.
void fill_random_phasors(MersenneTwister64& generator, std::complex<double>* out, std::size_t count);

struct TurbulenceStats {
  double iec_sigma_m_s[3] = {0, 0, 0};       // sigma_k of IEC: sigma_1, 0.8 sigma_1, 0.5 sigma_1 [m/s]
  double expected_sigma_m_s[3] = {0, 0, 0};  // sqrt(Σ_m S_k(f_m) Δf) of the discrete record [m/s]
  int frequencies = 0;                       // positive frequencies carried [-]
  int independent_frequencies = 0;           // u frequencies with coherence dropped (< 1e-4)
  int embedding_frequencies = 0;             // u frequencies by circulant embedding (exact)
  int dense_frequencies = 0;                 // u frequencies by dense Cholesky (exact)
  double max_dropped_coherence = 0.0;        // largest coherence replaced by 0 [-] (grid and tower)
  int tower_conditional_frequencies = 0;     // u frequencies with the tower drawn given the grid (exact)
  int tower_independent_frequencies = 0;     // u frequencies with the tower's coherences dropped (< 1e-4)
};

struct GeneratedTurbulence {
  FullField field;        // periodic grid centred on (y = 0, z = reference_height_m) and TurbSim's tower points
  TurbulenceStats stats;
};

// params.model must be turbulent (validated). Memory: the field (nt·ny·nz·3 float) plus one
// spectrum buffer (ny·nz·(nt/2+1) complex double) reused for the three components. With `held`,
// the field holds only the samples of the record a run reads — the same values as the whole
// record's (its spectra are the whole record's; only the transposes and the memory shrink).
struct HeldTimes {
  double until_s = 0.0;         // the latest (shifted) time the run reads [s]
  double before_start_s = 0.0;  // how far before 0 it reads, on the periodic record's end [s]
};
GeneratedTurbulence generate_turbulence(const WindParams& params, std::optional<HeldTimes> held = std::nullopt);

}  // namespace fowtsim::wind
