#pragma once
// Shape functions φ_m(x) of a slender body bending in one plane, x ∈ [0, L] measured along the
// body from its bottom end (seed 004, slide "Lagrange's Equation of Motion": v(x,t) = Σ φ_m q_m;
// the shapes carry the essential boundary conditions). Plain data: a family tag and its numbers,
// evaluated on demand, so a model stays copyable.
#include <vector>

namespace fowtsim::slender {

enum class ShapeKind {
  ClampedFreeMode,   // mode of the uniform cantilever clamped at x = 0, free at x = L
  FreeClampedMode,   // the same mirrored: clamped at the top x = L, free at the bottom x = 0 (a hanging body)
  Sine,              // sin(nπx/L): zero displacement and curvature at both ends (pinned–pinned)
  RigidTranslation,  // φ = 1: the whole body sways
  RigidRotation,     // φ = x − x_ref: the body rotates about x_ref (small angle)
};

struct ShapeFunction {
  ShapeKind kind;   // family
  int index;        // mode number n >= 1 (ClampedFreeMode, Sine); 0 for rigid shapes
  double length_m;  // L, the body's length [m]
  double parameter; // β_n [-] for ClampedFreeMode and FreeClampedMode, nπ [-] for Sine, x_ref [m] for RigidRotation
};

struct ShapeValue {
  double value;      // φ [-] (RigidRotation: [m], q is then the rotation in rad)
  double slope;      // φ' [1/m]
  double curvature;  // φ'' [1/m²]
};

ShapeValue evaluate(const ShapeFunction& shape, double x_m);

// β_n of 1 + cos β cosh β = 0, n >= 1 (1.8751, 4.6941, 7.8548, …), by Brent's method on
// cos β + 1/cosh β in [(n − ½)π − ½, (n − ½)π + ½] (the root lies within e^{−β} of (n − ½)π).
double clamped_free_beta(int n);

// The first `count` modes of a uniform clamped–free beam, scaled to φ(L) = ±2 (the textbook
// form cosh − cos − σ(sinh − sin)), evaluated without cancellation.
std::vector<ShapeFunction> clamped_free_shapes(int count, double length_m);
// The same mirrored, φ(x) = φ_cf(L − x): clamped at the top (a deck connection), free at the bottom.
std::vector<ShapeFunction> free_clamped_shapes(int count, double length_m);
// sin(nπx/L), n = 1 … count: pinned–pinned bodies (a top-tensioned riser).
std::vector<ShapeFunction> pinned_pinned_shapes(int count, double length_m);
// A floating body: translation, rotation about x_ref, then `flexible_count` sines. The sines vanish
// at both ends, so translation + rotation + sines span every smooth v(x) (the remainder after
// removing the straight line through v(0), v(L) is a sine series); their zero end curvature is the
// free end's moment condition.
std::vector<ShapeFunction> floating_shapes(int flexible_count, double length_m, double rotation_centre_m);

}  // namespace fowtsim::slender
