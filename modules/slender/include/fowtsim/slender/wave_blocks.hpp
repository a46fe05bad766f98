#pragma once
// Wave kinematics at the strips in blocks of half-step samples, for a time domain of any length
// in bounded memory (the stepping counterpart of wave_synthesis.hpp's whole-record histories, with
// the same sea: the same components, phases and sample times, equal to rounding).
//
// Regular wave: each sample analytically, u = Re(a U e^{iωt}) (harmonic_wave_history's arithmetic).
// Random sea: the seed's sum of harmonics y_k = Re Σ_j C_j e^{2πi (f + j) k / N} (ω_j = (f + j)Δω,
// N = 2π/(Δω · interval) samples per record), which random_wave_history sums by one FFT of the
// whole record per strip. Here a block of B samples from k0 takes the band's Nf components only,
// by Bluestein's chirp-z transform (jm = (j² + m² − (m − j)²)/2):
//   y_{k0+m} = Re[ e^{iπ(2f(k0+m) + m²)/N} Σ_j (C_j e^{iπ(2jk0 + j²)/N}) e^{−iπ(m−j)²/N} ],
// a linear convolution of length Nf + B − 1, taken cyclically by FFTs of length L (a power of two,
// at least 2 Nf, B = L − Nf + 1). The phases' integer exponents are reduced modulo 2N before the
// exponential, so every sample is accurate to rounding however far into the run it lies.
// Memory: strips × Nf coefficients and strips × B samples, neither growing with the run.
#include <memory>

#include "fowtsim/core/fft.hpp"
#include "fowtsim/slender/wave_synthesis.hpp"

namespace fowtsim::slender {

// The sea at the strips (immutable): what any block is made from.
struct WaveSource {
  double sample_interval_s = 0.0;    // samples at t_k = k · sample_interval_s
  Eigen::Index block_samples = 0;    // B, samples per block
  bool regular = true;
  // Regular wave.
  VecXc velocity_transfer;           // U per strip (N), u = Re(a U e^{iωt})
  double omega_rad_s = 0.0, amplitude_m = 0.0;
  // Random sea (Bluestein over the components).
  long record_samples = 0;           // N = 2π/(Δω · interval): the record repeats after it
  long first_index = 0;              // f: ω_j = (f + j)Δω
  MatXc velocity_coefficients;       // C_j of u per strip: a_j e^{iφ_j} U_ij (Nf × strips), a strip per column
  MatXc acceleration_coefficients;   // of u̇: iω_j a_j e^{iφ_j} U_ij (Nf × strips)
  VecXc elevation_coefficients;      // of η at the body: a_j e^{iφ_j} (Nf)
  VecXc chirp_spectrum;              // DFT of b_l = e^{−iπl²/N} on the cyclic grid of length L, over L (L)
};

// Samples [first_sample, first_sample + B) of the sea: a part of the scene's state.
struct WaveBlock {
  long first_sample = 0;
  VecX elevation_m;          // η at the body (B) [m]
  MatX velocity_m_s;         // u at each strip's kinematics point (N × B) [m/s]
  MatX acceleration_m_s2;    // u̇ (N × B) [m/s²]
};

// Scratch of fill_wave_block (the FFT's buffer and the block's phase factors), made once.
struct WaveBlockWorkspace {
  std::unique_ptr<ForwardComplexFft2d> fft;  // one row of L: the 1-D DFT (null for a regular wave)
  VecXc component_phase;                     // e^{iπ(2jk0 + j²)/N} (Nf)
  VecXc sample_phase;                        // e^{−iπ(2f(k0+m) + m²)/N} (B)
};

// velocity_transfer: U per strip (N). block_samples >= 3 (a step's three samples).
WaveSource harmonic_wave_source(const VecXc& velocity_transfer, double omega_rad_s, double amplitude_m,
                                double sample_interval_s, Eigen::Index block_samples);
// velocity_table: U (N × Nf). The same checks as random_wave_history (whole samples per record,
// every component below Nyquist), InputError otherwise.
WaveSource random_wave_source(const MatXc& velocity_table, const WaveComponents& components, double sample_interval_s);

WaveBlock make_wave_block(const WaveSource& source, Eigen::Index strips);  // sized, at sample 0, not filled
WaveBlockWorkspace make_wave_block_workspace(const WaveSource& source);
// Fills `block` with samples [first_sample, first_sample + B), first_sample >= 0; no allocation.
void fill_wave_block(const WaveSource& source, long first_sample, WaveBlockWorkspace& work, WaveBlock& block);

// Field list (core/fields.hpp).
template <class Archive>
void fields(Archive& a, WaveBlock& b) {
  a.io(b.first_sample, b.elevation_m, b.velocity_m_s, b.acceleration_m_s2);
}

}  // namespace fowtsim::slender
