#include "fowtsim/slender/wave_synthesis.hpp"

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/fft.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <string>

namespace fowtsim::slender {
namespace {

using std::numbers::pi;
using namespace std::complex_literals;

[[noreturn]] void fail(const std::string& variable, const std::string& hint, const std::string& message) {
  throw InputError({"slender.wave_synthesis", std::nullopt, variable, hint}, message);
}

// y_k = Re Σ_j c_j e^{i ω_j t_k} over one period of N samples, then tiled to `samples`.
VecX synthesise(InverseRealFft& fft, const VecXc& coefficients, int first_index, int samples) {
  fft.clear();
  // FFTW's c2r sums c_n e^{2πi kn/N} over n and N − n (conjugate): halving gives Re Σ c e^{…}.
  for (Eigen::Index j = 0; j < coefficients.size(); ++j) fft.coefficients()[first_index + j] = 0.5 * coefficients(j);
  const double* y = fft.execute();
  const auto N = fft.size();
  VecX out(samples);
  for (int k = 0; k < samples; ++k) out(k) = y[static_cast<std::size_t>(k) % N];
  return out;
}

}  // namespace

WaveHistory harmonic_wave_history(const VecXc& U, double omega, double amplitude, double interval, int samples) {
  WaveHistory h{interval, VecX(samples), MatX(U.size(), samples), MatX(U.size(), samples)};
  for (int k = 0; k < samples; ++k) {
    const std::complex<double> phasor = amplitude * std::exp(1i * (omega * k * interval));
    h.elevation_m(k) = phasor.real();
    h.velocity_m_s.col(k) = (U * phasor).real();
    h.acceleration_m_s2.col(k) = (U * (1i * omega * phasor)).real();
  }
  return h;
}

WaveComponents random_components(const VecX& spectrum, double delta_omega, int first_index, std::uint64_t seed) {
  if (!(delta_omega > 0.0) || first_index < 1) fail("delta_omega, first_index", "Δω > 0 and ω_0 = first_index·Δω > 0",
                                                    "Δω " + std::to_string(delta_omega) + ", first index " + std::to_string(first_index));
  std::mt19937_64 generator(seed);
  std::uniform_real_distribution<double> uniform(0.0, 2.0 * pi);
  WaveComponents c{delta_omega, first_index, (2.0 * spectrum.cwiseMax(0.0) * delta_omega).cwiseSqrt(), VecX(spectrum.size())};
  for (Eigen::Index j = 0; j < spectrum.size(); ++j) c.phase_rad(j) = uniform(generator);
  return c;
}

WaveHistory random_wave_history(const MatXc& U, const WaveComponents& c, double interval, int samples) {
  const double period_samples = 2.0 * pi / (c.delta_omega_rad_s * interval);
  const auto N = static_cast<std::size_t>(std::llround(period_samples));
  if (std::abs(period_samples - static_cast<double>(N)) > 1e-9 * period_samples)
    fail("sample_interval_s", "choose Δω = 2π/(N · sample interval)",
         "2π/(Δω·Δt) = " + std::to_string(period_samples) + " is not an integer");
  const auto Nf = c.amplitude_m.size();
  if (U.cols() != Nf) fail("velocity_table", "one column per wave component", "table and components differ in size");
  if (static_cast<std::size_t>(c.first_index + Nf) >= N / 2)
    fail("sample_interval_s", "sample faster than twice the highest wave frequency", "a component is at or above Nyquist");
  InverseRealFft fft(N);
  const VecXc components = c.amplitude_m.cast<std::complex<double>>().cwiseProduct(
      (1i * c.phase_rad.cast<std::complex<double>>()).array().exp().matrix());
  VecX omegas(Nf);
  for (Eigen::Index j = 0; j < Nf; ++j) omegas(j) = (c.first_index + j) * c.delta_omega_rad_s;
  WaveHistory h{interval, synthesise(fft, components, c.first_index, samples), MatX(U.rows(), samples),
                MatX(U.rows(), samples)};
  for (Eigen::Index i = 0; i < U.rows(); ++i) {
    const VecXc velocity = components.cwiseProduct(U.row(i).transpose());
    h.velocity_m_s.row(i) = synthesise(fft, velocity, c.first_index, samples).transpose();
    const VecXc acceleration = (1i * omegas.cast<std::complex<double>>()).cwiseProduct(velocity);
    h.acceleration_m_s2.row(i) = synthesise(fft, acceleration, c.first_index, samples).transpose();
  }
  return h;
}

}  // namespace fowtsim::slender
