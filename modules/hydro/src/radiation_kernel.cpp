#include "fowtsim/hydro/radiation_kernel.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "fowtsim/core/error.hpp"

namespace fowtsim::hydro {
namespace {

// ∫_a^b cos(ω t) dω and ∫_a^b ω cos(ω t) dω: a linear piece p + q ω of B integrates to p I0 + q I1,
// so each piece and time costs one pair of trigonometric evaluations for all 36 entries.
struct PieceIntegrals {
  double i0 = 0.0, i1 = 0.0;
};

PieceIntegrals piece_cosine_integrals(double a, double b, double t) {
  const double h = b - a;
  PieceIntegrals out;
  if (t * h < 0.1) {
    // 3-point Gauss–Legendre: exact to degree 5, error ~ (t h)^6 / 2e4 relative.
    constexpr std::array<double, 3> x = {-0.7745966692414834, 0.0, 0.7745966692414834};
    constexpr std::array<double, 3> w = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    for (int k = 0; k < 3; ++k) {
      const double omega = 0.5 * (a + b) + 0.5 * h * x[k];
      const double c = std::cos(omega * t);
      out.i0 += 0.5 * h * w[k] * c;
      out.i1 += 0.5 * h * w[k] * omega * c;
    }
    return out;
  }
  const double sa = std::sin(a * t), ca = std::cos(a * t), sb = std::sin(b * t), cb = std::cos(b * t);
  out.i0 = (sb - sa) / t;
  out.i1 = (b * sb - a * sa) / t + (cb - ca) / (t * t);
  return out;
}

}  // namespace

std::vector<Mat6> retardation_kernel(std::span<const double> frequencies_rad_s, std::span<const Mat6> damping,
                                     std::span<const double> times_s) {
  if (frequencies_rad_s.size() != damping.size() || frequencies_rad_s.empty())
    throw InputError({"hydro.radiation", std::nullopt, "damping", "one damping matrix per frequency"},
                     "the frequency and damping tables differ in length or are empty");
  std::vector<double> omega(frequencies_rad_s.begin(), frequencies_rad_s.end());
  std::vector<Mat6> b(damping.begin(), damping.end());
  if (omega.front() > 0.0) {  // B(0) = 0: no waves radiate at zero frequency
    omega.insert(omega.begin(), 0.0);
    b.insert(b.begin(), Mat6::Zero());
  }
  for (std::size_t k = 1; k < omega.size(); ++k)
    if (!(omega[k] > omega[k - 1]))
      throw InputError({"hydro.radiation", std::nullopt, "frequencies", "strictly ascending"}, "frequencies not ascending");
  // B on piece k is P_k + Q_k ω.
  std::vector<Mat6> slope(omega.size() - 1), offset(omega.size() - 1);
  for (std::size_t k = 0; k + 1 < omega.size(); ++k) {
    slope[k] = (b[k + 1] - b[k]) / (omega[k + 1] - omega[k]);
    offset[k] = b[k] - slope[k] * omega[k];
  }
  std::vector<Mat6> kernel(times_s.size(), Mat6::Zero());
  for (std::size_t n = 0; n < times_s.size(); ++n) {
    for (std::size_t k = 0; k + 1 < omega.size(); ++k) {
      const PieceIntegrals integrals = piece_cosine_integrals(omega[k], omega[k + 1], times_s[n]);
      kernel[n] += offset[k] * integrals.i0 + slope[k] * integrals.i1;
    }
    kernel[n] *= 2.0 / std::numbers::pi;
  }
  return kernel;
}

Mat6 added_mass_from_kernel(double omega_rad_s, std::span<const double> times_s, std::span<const Mat6> kernel,
                            const Mat6& added_mass_infinite_frequency) {
  Mat6 integral = Mat6::Zero();
  for (std::size_t n = 0; n + 1 < times_s.size(); ++n) {
    const double t0 = times_s[n], t1 = times_s[n + 1];
    integral += 0.5 * (t1 - t0) * (kernel[n] * std::sin(omega_rad_s * t0) + kernel[n + 1] * std::sin(omega_rad_s * t1));
  }
  return added_mass_infinite_frequency - integral / omega_rad_s;
}

}  // namespace fowtsim::hydro
