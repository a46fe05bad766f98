#include "fowtsim/slender/shape_functions.hpp"

#include "fowtsim/core/brent.hpp"
#include "fowtsim/core/error.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace fowtsim::slender {
namespace {

using std::numbers::pi;

void check(bool ok, const std::string& what, const std::string& message) {
  if (!ok) throw InputError({"slender.shapes", std::nullopt, what, "check the shape set"}, message);
}

// Clamped–free mode in y = βx/L: φ = cosh y − cos y − σ(sinh y − sin y),
// σ = (cosh β + cos β)/(sinh β + sin β). With σ = 1 − ε, cosh y − σ sinh y = e^{−y} + ε sinh y,
// ε = (sin β − cos β − e^{−β})/(sinh β + sin β) ≈ 2(sin β − cos β)e^{−β}: no term grows beyond
// O(1), where the textbook form cancels e^{y} (1e-3 lost by β = 30).
ShapeValue clamped_free(double beta, double length, double x) {
  const double y = beta * x / length, scale = beta / length;
  const double sigma_denominator = std::sinh(beta) + std::sin(beta);
  const double epsilon = (std::sin(beta) - std::cos(beta) - std::exp(-beta)) / sigma_denominator;
  const double sigma = 1.0 - epsilon;
  const double ey = std::exp(-y), sh = std::sinh(y), ch = std::cosh(y), s = std::sin(y), c = std::cos(y);
  return {ey + epsilon * sh - c + sigma * s,
          scale * (-ey + epsilon * ch + s + sigma * c),
          scale * scale * (ey + epsilon * sh + c - sigma * s)};
}

}  // namespace

ShapeValue evaluate(const ShapeFunction& shape, double x) {
  switch (shape.kind) {
    case ShapeKind::ClampedFreeMode:
      return clamped_free(shape.parameter, shape.length_m, x);
    case ShapeKind::FreeClampedMode: {  // x → L − x: the slope changes sign, the curvature does not
      const ShapeValue v = clamped_free(shape.parameter, shape.length_m, shape.length_m - x);
      return {v.value, -v.slope, v.curvature};
    }
    case ShapeKind::Sine: {
      const double k = shape.parameter / shape.length_m;
      return {std::sin(k * x), k * std::cos(k * x), -k * k * std::sin(k * x)};
    }
    case ShapeKind::RigidTranslation:
      return {1.0, 0.0, 0.0};
    case ShapeKind::RigidRotation:
      return {x - shape.parameter, 1.0, 0.0};
  }
  return {0.0, 0.0, 0.0};
}

double clamped_free_beta(int n) {
  check(n >= 1, "mode number", "clamped–free mode number " + std::to_string(n) + " (needs >= 1)");
  const auto f = [](double b) { return std::cos(b) + 1.0 / std::cosh(b); };
  const double centre = (n - 0.5) * pi, a = centre - 0.5, b = centre + 0.5;
  return brent_root(f, a, b, f(a), f(b), 1e-15, 200);
}

std::vector<ShapeFunction> clamped_free_shapes(int count, double length) {
  check(length > 0.0, "length", "body length " + std::to_string(length) + " m (needs > 0)");
  std::vector<ShapeFunction> shapes;
  for (int n = 1; n <= count; ++n)
    shapes.push_back({ShapeKind::ClampedFreeMode, n, length, clamped_free_beta(n)});
  return shapes;
}

std::vector<ShapeFunction> free_clamped_shapes(int count, double length) {
  std::vector<ShapeFunction> shapes = clamped_free_shapes(count, length);
  for (ShapeFunction& s : shapes) s.kind = ShapeKind::FreeClampedMode;
  return shapes;
}

std::vector<ShapeFunction> pinned_pinned_shapes(int count, double length) {
  check(length > 0.0, "length", "body length " + std::to_string(length) + " m (needs > 0)");
  std::vector<ShapeFunction> shapes;
  for (int n = 1; n <= count; ++n) shapes.push_back({ShapeKind::Sine, n, length, n * pi});
  return shapes;
}

std::vector<ShapeFunction> floating_shapes(int flexible_count, double length, double rotation_centre) {
  std::vector<ShapeFunction> shapes{{ShapeKind::RigidTranslation, 0, length, 0.0},
                                    {ShapeKind::RigidRotation, 0, length, rotation_centre}};
  for (const auto& s : pinned_pinned_shapes(flexible_count, length)) shapes.push_back(s);
  return shapes;
}

}  // namespace fowtsim::slender
