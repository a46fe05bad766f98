#pragma once
// Shape functions of a slender body bending in one plane, x ∈ [0, L] from the clamped root, in the
// seed's notation (Sec. 4.2): displacement u(x), slope ν = ∂u/∂x, curvature κ = ∂ν/∂x.
// All three kinds below are clamped at the root (u = ν = 0 at x = 0) and normalised to u(L) = 1.
#include <array>
#include <functional>
#include <string>

namespace fowtsim::flexbody {

struct ShapeValue {
  double u;      // [-] per unit generalised coordinate
  double nu;     // slope [1/m]
  double kappa;  // curvature [1/m^2]
};

class ShapeFunction {
 public:
  using Eval = std::function<ShapeValue(double x)>;
  ShapeFunction(std::string name, Eval eval) : name_(std::move(name)), eval_(std::move(eval)) {}
  ShapeValue operator()(double x) const { return eval_(x); }
  const std::string& name() const { return name_; }

 private:
  std::string name_;
  Eval eval_;
};

// ElastoDyn's mode-shape polynomial u = Σ_{j=2..6} c_j x̃^j, x̃ = x/L, coefficients {c2..c6} as in
// its tower and blade files. ElastoDyn requires Σ c_j = 1 within 0.001; the same check throws
// InputError here, and the polynomial is then divided by Σ c_j so that u(L) = 1 exactly.
ShapeFunction polynomial_shape(const std::array<double, 5>& c2_to_c6, double length);

// The seed's Sec. 5.1 single shape u_0 = 1 − cos(π x̃ / 2) (the mode of a massless beam with a top
// mass): M_q = mL(3π − 8)/(2π), K_q = EIπ⁴/(32L³), ∫ν_0² = π²/(8L).
ShapeFunction cosine_shape(double length);

// β_j of eq. 32: the root of 1 + cosh β cos β − β (M_t/M)(sin β cosh β − cos β sinh β) = 0 closest
// to (2j − 1)π/2, j >= 1; top_mass_ratio = M_t/M with M = mL. The root lies in [(j−1)π, jπ]
// (the residual, divided by cosh β, has sign (−1)^j at jπ) and is found by Brent's method.
double clamped_free_beta(int j, double top_mass_ratio = 0.0);

// Mode j of the uniform clamped-free beam with a top mass, eq. 32:
// u = S[cosh βx̃ − cos βx̃] − C[sinh βx̃ − sin βx̃], S = sinh β + sin β, C = cosh β + cos β,
// scaled to u(L) = 1 (welib's norm='tip'). The top mass enters through β only: u''(L) = 0 fixes
// C/S whatever M_t. ω_j = (β_j/L)² sqrt(EI/m).
ShapeFunction clamped_free_mode(int j, double length, double top_mass_ratio = 0.0);

}  // namespace fowtsim::flexbody
