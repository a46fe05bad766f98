#include "fowtsim/waves/spectrum.hpp"

#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::waves {
namespace {

constexpr double kSigmaBelow = 0.07;  // σ for ω ≤ ωp (IEC 61400-3, DNV-RP-C205 eq. 3.5.5)
constexpr double kSigmaAbove = 0.09;  // σ for ω > ωp

// ν⁻⁵ e^{−5/4 ν⁻⁴}: the Pierson–Moskowitz shape in ν = ω/ωp (0 where it underflows).
double pm_shape(double nu) {
  if (nu < 0.05) return 0.0;  // e^{−1.25·160000}: avoids ν⁻⁵ overflow times an underflowed 0
  const double inv4 = 1.0 / (nu * nu * nu * nu);
  return inv4 / nu * std::exp(-1.25 * inv4);
}

double peak_exponent(double nu) {
  const double sigma = nu <= 1.0 ? kSigmaBelow : kSigmaAbove;
  const double d = (nu - 1.0) / sigma;
  return std::exp(-0.5 * d * d);
}

// ∫ pm_shape(ν) (γ^{r(ν)} − 1) dν over [a, b] by composite Simpson with n (even) panels.
double peak_excess(double log_gamma, double a, double b, int n) {
  const auto f = [&](double nu) { return pm_shape(nu) * std::expm1(peak_exponent(nu) * log_gamma); };
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
  return sum * h / 3.0;
}

}  // namespace

double jonswap_normalisation(double gamma) {
  if (!(std::isfinite(gamma) && gamma >= 1.0))
    throw InputError({"waves.spectrum", std::nullopt, "gamma", "a peak-shape factor >= 1"},
                     fmt::format("JONSWAP peak-shape factor must be >= 1, found {}", gamma));
  if (gamma == 1.0) return 1.0;
  // I(γ) = 1/5 (Pierson–Moskowitz part, analytic) + the peak excess, which vanishes beyond 12 σ
  // (r < e^{−72}); split at the kink ν = 1 so Simpson keeps its fourth order (error ~ (h/σ)⁴/180).
  const double log_gamma = std::log(gamma);
  const int panels = 8192;
  const double excess = peak_excess(log_gamma, 1.0 - 12.0 * kSigmaBelow, 1.0, panels) +
                        peak_excess(log_gamma, 1.0, 1.0 + 12.0 * kSigmaAbove, panels);
  return 1.0 / (5.0 * (0.2 + excess));
}

double jonswap_density(double omega, double hs, double tp, double gamma, double normalisation) {
  if (!(omega > 0.0) || hs == 0.0) return 0.0;
  const double omega_p = 2.0 * std::numbers::pi / tp;
  const double nu = omega / omega_p;
  // 5/16 Hs² ωp⁴ ω⁻⁵ = 5/16 Hs² / ωp · ν⁻⁵
  const double pm = 0.3125 * hs * hs / omega_p * pm_shape(nu);
  return gamma == 1.0 ? normalisation * pm : normalisation * pm * std::pow(gamma, peak_exponent(nu));
}

double jonswap_density(double omega, double hs, double tp, double gamma) {
  return jonswap_density(omega, hs, tp, gamma, jonswap_normalisation(gamma));
}

double pierson_moskowitz_density(double omega, double hs, double tp) {
  return jonswap_density(omega, hs, tp, 1.0, 1.0);
}

}  // namespace fowtsim::waves
