#pragma once
// Wave kinematics histories at the strips for the time domain (seed 004, slides "Solution in Time
// Domain", constructWave.m). Regular wave: u = Re(a U e^{iωt}). Random wave: the seed's sum of
// harmonics of random phase, ω_j = jΔω equally spaced, a_j = √(2 S(ω_j) Δω) (the area under the
// spectrum segment is the component's variance a_j²/2), summed by one inverse FFT per strip.
// The record repeats after 2π/Δω.
#include "fowtsim/slender/wave_kinematics.hpp"

#include <cstdint>

namespace fowtsim::slender {

struct WaveHistory {
  double sample_interval_s;  // samples at t_k = k · sample_interval_s
  VecX elevation_m;          // η(t_k) at the body (samples), for post-processing
  MatX velocity_m_s;         // u at each strip's kinematics point (N × samples)
  MatX acceleration_m_s2;    // u̇ (N × samples)
};

WaveHistory harmonic_wave_history(const VecXc& velocity_transfer, double omega_rad_s, double amplitude_m,
                                  double sample_interval_s, int samples);

struct WaveComponents {
  double delta_omega_rad_s;  // Δω
  int first_index;           // ω_j = (first_index + j) Δω, first_index >= 1
  VecX amplitude_m;          // a_j = √(2 S_η(ω_j) Δω)
  VecX phase_rad;            // φ_j, uniform in [0, 2π)
};

// Amplitudes from S_η on ω_j = (first_index + j)Δω, phases from std::mt19937_64(seed).
WaveComponents random_components(const VecX& wave_spectrum_m2_s, double delta_omega_rad_s, int first_index,
                                 std::uint64_t seed);

// Sampling needs 2π/(Δω · sample_interval) to be an integer N (the FFT length) and every ω_j
// below the Nyquist frequency; samples beyond N repeat the record. velocity_table: U (N × Nf).
WaveHistory random_wave_history(const MatXc& velocity_table, const WaveComponents& components,
                                double sample_interval_s, int samples);

}  // namespace fowtsim::slender
