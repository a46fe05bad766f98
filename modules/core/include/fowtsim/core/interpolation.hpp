#pragma once
// One-dimensional interpolation on a strictly increasing grid (tables, time series).
#include <cstddef>
#include <span>

namespace fowtsim {

// Index i with x[i] <= xq < x[i+1], clamped to [0, n-2]. Binary search, O(log n).
std::size_t bracket_index(std::span<const double> x, double xq);

// Piecewise-linear interpolation; values outside [x.front(), x.back()] are held at the end
// values (no extrapolation). Throws InputError when sizes differ or fewer than 1 point is given.
double interpolate_linear(std::span<const double> x, std::span<const double> y, double xq);

// Throws InputError naming `what` unless x is strictly increasing.
void require_strictly_increasing(std::span<const double> x, const char* what);

// 4-point Lagrange interpolation on a periodic record of `samples` values y_j = y(j Δt), Δt =
// period/samples: the value at t is Σ_a weight[a] y[index[a]], nodes j−1 … j+2 around t (wrapped).
// Exact for cubics; a component of frequency ω is off by at most (9/16)/24 (ω Δt)⁴ of its amplitude.
// Throws NumericalError for a non-finite t.
struct PeriodicStencil {
  std::size_t index[4];
  double weight[4];
};
PeriodicStencil periodic_cubic_stencil(double t, double period, std::size_t samples);

// Linear blend a + s (b - a); s in [0, 1] gives points between a and b.
template <class T>
T lerp(const T& a, const T& b, double s) {
  return a + s * (b - a);
}

}  // namespace fowtsim
