#include "fowtsim/waves/wave_field.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>

#include <fmt/format.h>

#include "depth_factors.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/core/fft.hpp"
#include "fowtsim/waves/dispersion.hpp"
#include "fowtsim/waves/spectrum.hpp"
#include "synthesis.hpp"

namespace fowtsim::waves {
namespace {

constexpr double kPi = std::numbers::pi;

// Uniform double in (0, 1) from the top 53 bits of a 64-bit draw: (⌊x/2¹¹⌋ + ½) 2⁻⁵³. Our own
// conversion because std::uniform_real_distribution is implementation-defined (not portable
// bit for bit); never 0 or 1, so −ln u is finite.
double uniform_open(std::mt19937_64& rng) {
  return (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53;
}

}  // namespace

WaveField::WaveField(const WaveParams& p) : params_(p) {
  validate(p);
  gamma_ = waves::peak_shape(p);
  const double heading = p.heading_deg * kPi / 180.0;
  direction_ = Vec3(std::cos(heading), std::sin(heading), 0.0);
  const double calm_dt = p.dt_s > 0.0 && std::isfinite(p.dt_s) ? p.dt_s : 1.0;
  samples_ = 4;
  duration_s_ = 4.0 * calm_dt;

  if (p.model == WaveModel::regular && p.height_m > 0.0) {
    samples_ = std::max<std::size_t>(8, static_cast<std::size_t>(std::ceil(p.period_s / p.dt_s * (1.0 - 1e-12))));
    duration_s_ = p.period_s;
    WaveComponent w;
    w.harmonic = 1;
    w.omega_rad_s = 2.0 * kPi / p.period_s;
    w.wavenumber_rad_m = wavenumber(w.omega_rad_s, p.depth_m, p.gravity_m_s2);
    const double phase = p.phase_deg * kPi / 180.0;
    w.amplitude_m = 0.5 * p.height_m * std::complex<double>(std::cos(phase), std::sin(phase));
    components_.push_back(w);
    spectral_m0_ = expected_m0_ = 0.125 * p.height_m * p.height_m;
  } else if (p.model == WaveModel::jonswap || p.model == WaveModel::pierson_moskowitz) {
    const auto n_samples = static_cast<std::size_t>(std::llround(p.duration_s / p.dt_s));
    const double d_omega = 2.0 * kPi / p.duration_s;
    const double normalisation = jonswap_normalisation(gamma_);
    const double f_low = p.cutoff_low_hz;
    const double f_high = p.cutoff_high_hz ? *p.cutoff_high_hz : 0.5 / p.dt_s;
    spectral_m0_ = p.hs_m * p.hs_m / 16.0;
    std::mt19937_64 rng(p.seed);
    std::vector<WaveComponent> kept;
    for (std::size_t n = 1; 2 * n < n_samples; ++n) {
      const double u_phase = uniform_open(rng);
      const double u_amplitude = uniform_open(rng);
      const double f = static_cast<double>(n) / p.duration_s;
      if (f < f_low || f > f_high) continue;
      WaveComponent w;
      w.harmonic = n;
      w.omega_rad_s = d_omega * static_cast<double>(n);
      const double density = jonswap_density(w.omega_rad_s, p.hs_m, p.tp_s, gamma_, normalisation);
      if (!(density > 0.0)) continue;
      expected_m0_ += density * d_omega;
      double a = std::sqrt(2.0 * density * d_omega);
      if (p.rayleigh_amplitudes) a *= std::sqrt(-std::log(u_amplitude));
      const double phase = 2.0 * kPi * u_phase;
      w.amplitude_m = a * std::complex<double>(std::cos(phase), std::sin(phase));
      w.wavenumber_rad_m = wavenumber(w.omega_rad_s, p.depth_m, p.gravity_m_s2);
      kept.push_back(w);
    }
    if (!kept.empty()) {
      components_ = std::move(kept);
      samples_ = n_samples;
      duration_s_ = p.duration_s;
    }
  } else if (p.model == WaveModel::elevation_series) {
    // Replayed sea (elevation_record.hpp, README "Replaying a sea"; OpenFAST SeaState WaveMod 5).
    const ElevationRecord& record = *p.elevation_record;  // present: validate() checked it
    const RecordGrid grid = check_elevation_record(record);
    const std::size_t n_samples = grid.samples;
    ForwardRealFft fft(n_samples);
    std::copy(record.elevation_m.begin(), record.elevation_m.end(), fft.samples());
    const std::complex<double>* x = fft.execute();  // X_n = Σ_j η_j e^{−2πi jn/N}
    const double n_double = static_cast<double>(n_samples);
    removed_mean_m_ = x[0].real() / n_double;        // X₀/N: dropped with the n = 0 term
    const double d_omega = 2.0 * kPi / grid.duration_s;
    const double f_low = p.cutoff_low_hz;
    const double f_high = p.cutoff_high_hz ? *p.cutoff_high_hz : 0.5 / grid.step_s;
    const double start_turns = grid.start_s / grid.duration_s;  // t₀/D
    std::vector<WaveComponent> kept;
    // η_j − mean = (1/N) Σ_{n=1}^{N−1} X_n e^{2πi jn/N} = Σ_{0<n<N/2} Re[(2/N) X_n e^{2πi jn/N}]
    // + (X_{N/2}/N) (−1)^j for even N, and 2π jn/N = ω_n (t_j − t₀): hence A_n = (2/N) X_n e^{−iω_n t₀},
    // and A_{N/2} = (X_{N/2}/N) e^{−iω_{N/2} t₀} (X_{N/2} is real). The Nyquist term is kept so that the
    // record is reproduced exactly (a window of a longer sea leaks into it: mm on a metre sea); its
    // sine part, invisible at the samples, is taken as zero (the band-limited interpolant).
    for (std::size_t n = 1; 2 * n <= n_samples; ++n) {
      const double f = static_cast<double>(n) / grid.duration_s;
      if (f < f_low || f > f_high) continue;
      if (x[n] == std::complex<double>(0.0, 0.0)) continue;
      // ω_n t₀ = 2π (n t₀/D), reduced to a fraction of a turn first so a late start keeps its digits.
      const double turns = std::fmod(static_cast<double>(n) * start_turns, 1.0);
      WaveComponent w;
      w.harmonic = n;
      w.omega_rad_s = d_omega * static_cast<double>(n);
      const double scale = (2 * n == n_samples ? 1.0 : 2.0) / n_double;
      w.amplitude_m = scale * x[n] * std::polar(1.0, -2.0 * kPi * turns);
      w.wavenumber_rad_m = wavenumber(w.omega_rad_s, p.depth_m, p.gravity_m_s2);
      spectral_m0_ += 0.5 * std::norm(w.amplitude_m);
      kept.push_back(w);
    }
    expected_m0_ = spectral_m0_;
    if (!kept.empty()) {
      components_ = std::move(kept);
      samples_ = n_samples;
      duration_s_ = grid.duration_s;
    }
  }
}

double WaveField::highest_wavenumber_rad_m() const {
  return components_.empty() ? 0.0 : components_.back().wavenumber_rad_m;
}

double WaveField::record_m0_m2() const {
  double m0 = 0.0;
  for (const WaveComponent& w : components_) m0 += 0.5 * std::norm(w.amplitude_m);
  return m0;
}

double WaveField::elevation(double x, double y, double t) const {
  const double s = x * direction_.x() + y * direction_.y();
  double eta = 0.0;
  for (const WaveComponent& w : components_) {
    const double theta = w.omega_rad_s * t - w.wavenumber_rad_m * s;
    eta += w.amplitude_m.real() * std::cos(theta) - w.amplitude_m.imag() * std::sin(theta);
  }
  return eta;
}

WaveKinematics WaveField::evaluate(const Vec3& p, double t) const { return evaluate(p, t, params_.stretching); }

WaveKinematics WaveField::evaluate(const Vec3& p, double t, Stretching stretching) const {
  if (!std::isfinite(t))
    throw NumericalError({"waves", std::nullopt, "time", "check the time handed to the wave field"},
                         fmt::format("non-finite time {}", t));
  if (!p.allFinite())
    throw NumericalError({"waves", t, "evaluation point", "check the motion of the point"},
                         fmt::format("non-finite point ({}, {}, {})", p.x(), p.y(), p.z()));
  const double h = params_.depth_m;
  double z = p.z();
  if (z < -h) {
    if (z < -h - 1e-9 * std::max(1.0, h))
      throw InputError({"waves", t, "evaluation point z", "points must lie at or above the seabed z = -depth_m"},
                       fmt::format("point ({}, {}, {}) is below the seabed at z = {} m", p.x(), p.y(), z, -h));
    z = -h;  // round-off at the seabed
  }

  WaveKinematics out;
  out.elevation_m = elevation(p.x(), p.y(), t);
  const double eta = out.elevation_m;
  double z_field = z;
  if (stretching == Stretching::none) {
    if (z > 0.0) return out;
  } else {
    // Dry above the surface; a trough at or below the seabed leaves no water column (dry too).
    if (z > eta || !(h + eta > 0.0)) return out;
    z_field = std::isinf(h) ? z - eta : std::clamp(h * (z - eta) / (h + eta), -h, 0.0);
  }
  out.wetted = true;

  const double s = p.x() * direction_.x() + p.y() * direction_.y();
  const double rho_g = params_.water_density_kg_m3 * params_.gravity_m_s2;
  double u_h = 0.0, w_z = 0.0, a_h = 0.0, a_z = 0.0, p_d = 0.0;
  for (const WaveComponent& w : components_) {
    const double theta = w.omega_rad_s * t - w.wavenumber_rad_m * s;
    const double c = std::cos(theta), sn = std::sin(theta);
    const double re = w.amplitude_m.real() * c - w.amplitude_m.imag() * sn;  // Re[A e^{iθ}]
    const double im = w.amplitude_m.real() * sn + w.amplitude_m.imag() * c;  // Im[A e^{iθ}]
    const detail::DepthFactors f = detail::depth_factors(w.wavenumber_rad_m, z_field, h);
    const double om = w.omega_rad_s;
    u_h += om * f.cosh_over_sinh * re;
    w_z -= om * f.sinh_over_sinh * im;
    a_h -= om * om * f.cosh_over_sinh * im;
    a_z -= om * om * f.sinh_over_sinh * re;
    p_d += rho_g * f.cosh_over_cosh * re;
  }
  out.velocity_m_s = Vec3(direction_.x() * u_h, direction_.y() * u_h, w_z);
  out.acceleration_m_s2 = Vec3(direction_.x() * a_h, direction_.y() * a_h, a_z);
  out.dynamic_pressure_Pa = p_d;
  return out;
}

std::vector<double> WaveField::elevation_series(double x, double y, std::size_t oversampling) const {
  if (oversampling < 1)
    throw InputError({"waves", std::nullopt, "oversampling", "use 1 or more"}, "oversampling must be >= 1");
  std::vector<double> series(samples_ * oversampling, 0.0);
  if (calm()) return series;
  InverseRealFft fft(series.size());
  const double s = x * direction_.x() + y * direction_.y();
  detail::synthesise(*this, fft, s, [](const WaveComponent&) { return std::complex<double>(1.0, 0.0); },
                     series.data(), 1);
  return series;
}

}  // namespace fowtsim::waves
