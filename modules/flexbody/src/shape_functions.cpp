#include "fowtsim/flexbody/shape_functions.hpp"

#include "fowtsim/core/brent.hpp"
#include "fowtsim/core/error.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace fowtsim::flexbody {
namespace {

void check_length(double length) {
  if (!(length > 0.0))
    throw InputError({"flexbody", std::nullopt, "length", "give the body's length L > 0"},
                     "shape function on a body of length " + std::to_string(length));
}

// Eq. 32 without its scale, in y = β x̃, and its first two y-derivatives. Rewritten so that no
// term exceeds e^β (the size of the mode itself): S cosh y − C sinh y = sinh(β − y)
// + sin β cosh y − cos β sinh y. The textbook form loses e^y of precision (1e-11 at β = 11).
ShapeValue eq32_raw(double beta, double y) {
  const double S = std::sinh(beta) + std::sin(beta), C = std::cosh(beta) + std::cos(beta);
  const double sb = std::sin(beta), cb = std::cos(beta);
  const double ch = std::cosh(y), sh = std::sinh(y), c = std::cos(y), s = std::sin(y);
  return {std::sinh(beta - y) + sb * ch - cb * sh - S * c + C * s,
          -std::cosh(beta - y) + sb * sh - cb * ch + S * s + C * c,
          std::sinh(beta - y) + sb * ch - cb * sh + S * c - C * s};
}

}  // namespace

ShapeFunction polynomial_shape(const std::array<double, 5>& c, double length) {
  check_length(length);
  double sum = 0.0;
  for (double cj : c) sum += cj;
  if (std::abs(sum - 1.0) > 1e-3)
    throw InputError({"flexbody", std::nullopt, "mode-shape coefficients",
                      "the coefficients c2..c6 must add up to 1 (ElastoDyn's rule)"},
                     "coefficients sum to " + std::to_string(sum));
  return ShapeFunction("polynomial", [c, sum, length](double x) {
    const double t = x / length;
    ShapeValue v{0.0, 0.0, 0.0};
    for (int j = 2; j <= 6; ++j) {
      const double cj = c[j - 2] / sum;
      v.u += cj * std::pow(t, j);
      v.nu += cj * j * std::pow(t, j - 1) / length;
      v.kappa += cj * j * (j - 1) * std::pow(t, j - 2) / (length * length);
    }
    return v;
  });
}

ShapeFunction cosine_shape(double length) {
  check_length(length);
  return ShapeFunction("1 - cos(pi x / 2L)", [length](double x) {
    const double k = std::numbers::pi / (2.0 * length);
    return ShapeValue{1.0 - std::cos(k * x), k * std::sin(k * x), k * k * std::cos(k * x)};
  });
}

double clamped_free_beta(int j, double top_mass_ratio) {
  if (j < 1 || !(top_mass_ratio >= 0.0))
    throw InputError({"flexbody", std::nullopt, "mode index / top-mass ratio",
                      "modes count from 1; M_t/M >= 0"},
                     "clamped-free mode " + std::to_string(j) + " with M_t/M = " +
                         std::to_string(top_mass_ratio));
  // Eq. 32's frequency equation divided by cosh β (bounded for any β).
  const auto residual = [mu = top_mass_ratio](double b) {
    return 1.0 / std::cosh(b) + std::cos(b) - b * mu * (std::sin(b) - std::cos(b) * std::tanh(b));
  };
  const double a = (j - 1) * std::numbers::pi, b = j * std::numbers::pi;
  return brent_root(residual, a, b, residual(a), residual(b), 1e-14, 200);
}

ShapeFunction clamped_free_mode(int j, double length, double top_mass_ratio) {
  check_length(length);
  const double beta = clamped_free_beta(j, top_mass_ratio);
  const double tip = eq32_raw(beta, beta).u;
  return ShapeFunction("clamped-free mode " + std::to_string(j), [beta, tip, length](double x) {
    const ShapeValue r = eq32_raw(beta, beta * x / length);
    const double k = beta / length;
    return ShapeValue{r.u / tip, r.nu * k / tip, r.kappa * k * k / tip};
  });
}

}  // namespace fowtsim::flexbody
