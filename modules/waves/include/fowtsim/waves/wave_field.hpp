#pragma once
// The incident sea as a sum of linear (Airy) components, built once from WaveParams, immutable.
//
// Elevation (frame of DESIGN.md §3, z up from the still-water level):
//   η(x, y, t) = Σ_n Re[A_n e^{iθ_n}],   θ_n = ω_n t − k_n (x cos β + y sin β),
// with complex amplitudes A_n = a_n e^{iφ_n}, ω_n = 2π n / D on the harmonics of the record length D
// (so the record repeats with period D, as HydroDyn's), k_n from ω² = g k tanh(k h).
// Velocity, local acceleration and dynamic pressure of each component (e = (cos β, sin β, 0)):
//   u_h = e Re[ω A F_cs e^{iθ}],        w = Re[i ω A F_ss e^{iθ}],
//   a_h = e Re[i ω² A F_cs e^{iθ}],     a_z = −Re[ω² A F_ss e^{iθ}],
//   p_d = ρ g Re[A F_cc e^{iθ}],
//   F_cs = cosh k(z+h)/sinh kh,  F_ss = sinh k(z+h)/sinh kh,  F_cc = cosh k(z+h)/cosh kh
// (Dean & Dalrymple, Water Wave Mechanics, §4.4; for a regular wave η = a cos θ these are
// u_h = aω F_cs cos θ, w = −aω F_ss sin θ, p_d = ρ g a F_cc cos θ). The depth factors are evaluated
// as e^{kz}(1 ± e^{−2k(z+h)})/(1 ∓ e^{−2kh}) so they neither overflow in deep water nor lose digits in
// shallow water; h = +∞ gives e^{kz}. The acceleration is the local ∂v/∂t of linear theory (no
// convective term), as in HydroDyn. p_d is the pressure in excess of hydrostatic −ρ g z.
//
// Where the field applies (Stretching):
//   none:    the linear field at the point's own z for −h ≤ z ≤ 0, whatever η is (also in a trough
//            below z); zero for z > 0. (HydroDyn WaveStMod = 0.)
//   wheeler: for −h ≤ z ≤ η the linear field at z' = h (z − η)/(h + η) (z' = z − η for h = ∞), so the
//            surface values apply at the instantaneous surface and the seabed stays at −h; zero for
//            z > η, and wherever a trough reaches the seabed (h + η ≤ 0: no water column). Velocity,
//            acceleration and pressure are all stretched (HydroDyn WaveStMod = 3 stretches velocity
//            and acceleration). No dz'/dt term is added to the acceleration.
//   A point below the seabed (z < −h) is an InputError, never a NaN.
#include <complex>
#include <cstddef>
#include <span>
#include <vector>

#include "fowtsim/core/types.hpp"
#include "fowtsim/waves/wave_params.hpp"

namespace fowtsim::waves {

struct WaveKinematics {
  double elevation_m = 0.0;                   // η at the point's (x, y) [m], + up from still water
  Vec3 velocity_m_s = Vec3::Zero();           // particle velocity, inertial frame [m/s]
  Vec3 acceleration_m_s2 = Vec3::Zero();      // local particle acceleration ∂v/∂t, inertial [m/s²]
  double dynamic_pressure_Pa = 0.0;           // p − p_atm + ρ g z (excess over hydrostatic) [Pa]
  bool wetted = false;                        // the field applies at the point (Stretching rules)
};

struct WaveComponent {
  double omega_rad_s = 0.0;                   // ω_n = 2π n / D [rad/s]
  double wavenumber_rad_m = 0.0;              // k_n [rad/m]
  std::complex<double> amplitude_m;           // A_n = a_n e^{iφ_n} [m] (η at the origin, t = 0)
  std::size_t harmonic = 0;                   // n: harmonic of the record (FFT bin)
};

class WaveField {
 public:
  // Validates params (InputError listing every problem), solves the dispersion relation and
  // draws the random phases/amplitudes:
  //   irregular: N = D/dt samples; harmonics n = 1 … ⌈N/2⌉ − 1 (no mean, no Nyquist term); for every
  //     harmonic, in order, two uniforms u₁ (phase), u₂ (amplitude) are drawn from
  //     std::mt19937_64(seed) as u = (⌊x / 2¹¹⌋ + ½) 2⁻⁵³ ∈ (0, 1) — also for harmonics outside the
  //     cut-offs, so changing a cut-off keeps the phases of the others; φ_n = 2π u₁ and
  //     a_n = √(2 S(ω_n) Δω) (deterministic) or √(2 S Δω) √(−ln u₂) (Rayleigh: E[a²/2] = S Δω);
  //     components with f_n outside [cutoff_low_hz, cutoff_high_hz] are dropped.
  //   regular: one component A = H/2 e^{iφ} at harmonic 1 of a record of one period D = T, sampled
  //     at N = max(⌈T/dt⌉, 8) points (dt' = T/N ≤ dt).
  //   elevation_series: the N record samples, by one forward FFT (elevation_record.hpp): D = N Δt,
  //     A_n = (2/N) X_n e^{−iω_n t₀} for n = 1 … ⌊N/2⌋ inside the cut-offs (mean dropped; the Nyquist
  //     term of an even N kept, with 1/N), so η(0, 0, t_j) = η_j − mean; the sea repeats with period D.
  //   still (or Hs = 0, H = 0, a constant record): no components; a calm record of 4 samples.
  explicit WaveField(const WaveParams& params);

  const WaveParams& params() const { return params_; }
  double peak_shape() const { return gamma_; }                   // γ in use (1 unless jonswap)
  double depth_m() const { return params_.depth_m; }             // h [m] (+∞ = deep)
  const Vec3& direction() const { return direction_; }           // e = (cos β, sin β, 0)
  double record_duration_s() const { return duration_s_; }       // D: the record repeats with this period [s]
  double record_dt_s() const { return duration_s_ / static_cast<double>(samples_); }  // D / N [s]
  std::size_t record_samples() const { return samples_; }        // N
  std::span<const WaveComponent> components() const { return components_; }  // ascending ω
  bool calm() const { return components_.empty(); }
  double highest_wavenumber_rad_m() const;                       // k of the highest component (0 if calm)

  // Spectral bookkeeping (irregular seas; regular: a²/2 and the same; elevation_series: the variance
  // of the kept components, both; still: 0).
  double spectral_m0_m2() const { return spectral_m0_; }   // ∫₀^∞ S dω of the continuous spectrum = Hs²/16
  double expected_m0_m2() const { return expected_m0_; }   // Σ S(ω_n) Δω over the kept harmonics
  double record_m0_m2() const;                             // Σ |A_n|²/2: the variance of the record
  double removed_mean_m() const { return removed_mean_m_; }  // elevation_series: mean of the record
                                                           //   samples, removed [m]; 0 otherwise

  // Direct evaluation by summation over the components (any point, any time; for checks and moving
  // points). Cost O(number of components). Stretching as in params() unless given.
  // Throws InputError below the seabed (beyond round-off), NumericalError for non-finite p or t.
  WaveKinematics evaluate(const Vec3& p_m, double t_s) const;
  WaveKinematics evaluate(const Vec3& p_m, double t_s, Stretching stretching) const;
  double elevation(double x_m, double y_m, double t_s) const;

  // η at (x, y) at t_j = j D/(N m), j = 0 … N m − 1, by one inverse FFT (m = oversampling ≥ 1:
  // zero-padded, i.e. the band-limited interpolant of the record).
  std::vector<double> elevation_series(double x_m, double y_m, std::size_t oversampling = 1) const;

 private:
  WaveParams params_;
  double gamma_ = 1.0;
  Vec3 direction_ = Vec3::UnitX();
  double duration_s_ = 0.0;
  std::size_t samples_ = 0;
  std::vector<WaveComponent> components_;
  double spectral_m0_ = 0.0;
  double expected_m0_ = 0.0;
  double removed_mean_m_ = 0.0;
};

}  // namespace fowtsim::waves
