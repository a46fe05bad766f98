#include "fowtsim/slender/wave_blocks.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include "fowtsim/core/error.hpp"

namespace fowtsim::slender {
namespace {

using std::numbers::pi;
using namespace std::complex_literals;
using Complex = std::complex<double>;

[[noreturn]] void fail(const std::string& variable, const std::string& hint, const std::string& message) {
  throw InputError({"slender.wave_blocks", std::nullopt, variable, hint}, message);
}

// e^{iπ E/N} for an integer exponent E, reduced modulo 2N first (the period of the phase) so that
// the angle is in [0, 2π) and exact to one rounding whatever E was.
Complex half_turns(long exponent, long N) {
  const long reduced = exponent % (2 * N);
  return std::polar(1.0, pi * static_cast<double>(reduced) / static_cast<double>(N));
}

// One series of a block: y_m = Re[Q̄_m · DFT(conj(DFT(a) ⊙ b̂))_m] with a_j = C_j P_j (zero-padded to
// L): Bluestein's convolution through forward transforms only (the inverse DFT of X is the
// conjugate of the forward DFT of X̄, over L; the 1/L is in b̂). Writes `out` (B, any stride).
template <class Out>
void synthesise(const WaveSource& source, const Eigen::Ref<const VecXc>& coefficients, WaveBlockWorkspace& work, Out&& out) {
  const Eigen::Index Nf = coefficients.size(), L = source.chirp_spectrum.size();
  Eigen::Map<VecXc> data(work.fft->data(), L);
  data.head(Nf) = coefficients.cwiseProduct(work.component_phase);
  data.tail(L - Nf).setZero();
  work.fft->execute();
  data = data.cwiseProduct(source.chirp_spectrum).conjugate();
  work.fft->execute();
  out = work.sample_phase.cwiseProduct(data.head(source.block_samples)).real();
}

}  // namespace

WaveSource harmonic_wave_source(const VecXc& U, double omega, double amplitude, double interval, Eigen::Index block_samples) {
  if (block_samples < 3) fail("block_samples", "at least a step's three samples", "blocks of " + std::to_string(block_samples));
  WaveSource s;
  s.sample_interval_s = interval;
  s.block_samples = block_samples;
  s.regular = true;
  s.velocity_transfer = U;
  s.omega_rad_s = omega;
  s.amplitude_m = amplitude;
  return s;
}

WaveSource random_wave_source(const MatXc& U, const WaveComponents& c, double interval) {
  // random_wave_history's checks: the components must be periodic on the sample grid, below Nyquist.
  const double period_samples = 2.0 * pi / (c.delta_omega_rad_s * interval);
  const long N = std::lround(period_samples);
  if (std::abs(period_samples - static_cast<double>(N)) > 1e-9 * period_samples)
    fail("sample_interval_s", "choose Δω = 2π/(N · sample interval)",
         "2π/(Δω·Δt) = " + std::to_string(period_samples) + " is not an integer");
  const auto Nf = c.amplitude_m.size();
  if (U.cols() != Nf) fail("velocity_table", "one column per wave component", "table and components differ in size");
  if (Nf < 1) fail("components", "at least one wave component", "an empty sea");
  if (c.first_index + Nf >= N / 2)
    fail("sample_interval_s", "sample faster than twice the highest wave frequency", "a component is at or above Nyquist");
  // The exponents 2jk0 + j² and 2f(k0 + m) + m² (k0 < N, m < B < 4 Nf < 2N) stay below 2^63.
  if (N > (1L << 30)) fail("sample_interval_s", "a record of at most 2^30 samples", std::to_string(N) + " samples per record");

  WaveSource s;
  s.sample_interval_s = interval;
  s.regular = false;
  s.record_samples = N;
  s.first_index = c.first_index;
  Eigen::Index L = 256;
  while (L < 2 * Nf) L *= 2;
  s.block_samples = L - Nf + 1;
  // The coefficients as random_wave_history forms them: a_j e^{iφ_j}, times U, times iω_j.
  s.elevation_coefficients = c.amplitude_m.cast<Complex>().cwiseProduct((1i * c.phase_rad.cast<Complex>()).array().exp().matrix());
  s.velocity_coefficients.resize(Nf, U.rows());
  s.acceleration_coefficients.resize(Nf, U.rows());
  for (Eigen::Index i = 0; i < U.rows(); ++i) {
    s.velocity_coefficients.col(i) = s.elevation_coefficients.cwiseProduct(U.row(i).transpose());
    for (Eigen::Index j = 0; j < Nf; ++j) {
      const double omega = static_cast<double>(c.first_index + j) * c.delta_omega_rad_s;
      s.acceleration_coefficients(j, i) = (1i * omega) * s.velocity_coefficients(j, i);
    }
  }
  // b_l = e^{−iπl²/N} for l = −(Nf − 1) … B − 1, at l mod L; its DFT over L.
  ForwardComplexFft2d fft(1, static_cast<std::size_t>(L));
  Eigen::Map<VecXc> b(fft.data(), L);
  for (long l = -(Nf - 1); l < s.block_samples; ++l) b((l + L) % L) = std::conj(half_turns(l * l, N));
  fft.execute();
  s.chirp_spectrum = b / static_cast<double>(L);
  return s;
}

WaveBlock make_wave_block(const WaveSource& s, Eigen::Index strips) {
  const Eigen::Index B = s.block_samples;
  return {0, VecX::Zero(B), MatX::Zero(strips, B), MatX::Zero(strips, B)};
}

WaveBlockWorkspace make_wave_block_workspace(const WaveSource& s) {
  if (s.regular) return {};
  const Eigen::Index L = s.chirp_spectrum.size();
  return {std::make_unique<ForwardComplexFft2d>(1, static_cast<std::size_t>(L)), VecXc(s.elevation_coefficients.size()),
          VecXc(s.block_samples)};
}

void fill_wave_block(const WaveSource& s, long first, WaveBlockWorkspace& work, WaveBlock& b) {
  b.first_sample = first;
  const Eigen::Index B = s.block_samples;
  if (s.regular) {  // harmonic_wave_history's arithmetic, sample by sample
    for (Eigen::Index m = 0; m < B; ++m) {
      const long k = first + m;
      const Complex phasor = s.amplitude_m * std::exp(1i * (s.omega_rad_s * static_cast<double>(k) * s.sample_interval_s));
      b.elevation_m(m) = phasor.real();
      b.velocity_m_s.col(m) = (s.velocity_transfer * phasor).real();
      b.acceleration_m_s2.col(m) = (s.velocity_transfer * (1i * s.omega_rad_s * phasor)).real();
    }
    return;
  }
  const long N = s.record_samples, f = s.first_index, k0 = first % N;
  for (Eigen::Index j = 0; j < work.component_phase.size(); ++j) work.component_phase(j) = half_turns(2 * j * k0 + j * j, N);
  for (Eigen::Index m = 0; m < B; ++m) work.sample_phase(m) = std::conj(half_turns(2 * f * (k0 + m) + m * m, N));
  synthesise(s, s.elevation_coefficients, work, b.elevation_m);
  for (Eigen::Index i = 0; i < b.velocity_m_s.rows(); ++i) {
    synthesise(s, s.velocity_coefficients.col(i), work, b.velocity_m_s.row(i).transpose());
    synthesise(s, s.acceleration_coefficients.col(i), work, b.acceleration_m_s2.row(i).transpose());
  }
}

}  // namespace fowtsim::slender
