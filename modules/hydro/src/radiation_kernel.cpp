#include "fowtsim/hydro/radiation_kernel.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "fowtsim/core/error.hpp"

namespace fowtsim::hydro {
namespace {

// ∫_a^b (p + q ω) cos(ω t) dω for the linear piece p + q ω.
double piece_cosine_integral(double a, double b, double p, double q, double t) {
  const double h = b - a;
  if (t * h < 0.1) {
    // 3-point Gauss–Legendre: exact to degree 5, error ~ (t h)^6 / 2e4 relative.
    constexpr std::array<double, 3> x = {-0.7745966692414834, 0.0, 0.7745966692414834};
    constexpr std::array<double, 3> w = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double omega = 0.5 * (a + b) + 0.5 * h * x[k];
      sum += w[k] * (p + q * omega) * std::cos(omega * t);
    }
    return 0.5 * h * sum;
  }
  const auto antiderivative = [&](double omega) {
    return (p + q * omega) * std::sin(omega * t) / t + q * std::cos(omega * t) / (t * t);
  };
  return antiderivative(b) - antiderivative(a);
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
  std::vector<Mat6> kernel(times_s.size(), Mat6::Zero());
  for (std::size_t n = 0; n < times_s.size(); ++n) {
    for (std::size_t k = 0; k + 1 < omega.size(); ++k) {
      const double a = omega[k], h = omega[k + 1] - a;
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
          const double q = (b[k + 1](i, j) - b[k](i, j)) / h, p = b[k](i, j) - q * a;
          if (p != 0.0 || q != 0.0) kernel[n](i, j) += piece_cosine_integral(a, omega[k + 1], p, q, times_s[n]);
        }
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
