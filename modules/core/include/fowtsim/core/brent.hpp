#pragma once
// Brent's method (Brent 1973, "Algorithms for minimization without derivatives", ch. 4) for a
// root of f on a bracket [a, b] with f(a) f(b) <= 0: inverse quadratic interpolation or secant
// steps, bisection whenever they would leave the bracket or converge slowly. Always converges.
// A template so that the residual inlines: the induction solver calls it at every blade node.
#include <algorithm>
#include <cmath>
#include <limits>

namespace fowtsim {

// Returns x with |x − root| <= 2 ε |x| + tolerance/2 (ε the machine epsilon), or the last iterate
// after max_iterations. fa = f(a) and fb = f(b) are passed in: callers have them from bracketing.
template <class F>
double brent_root(const F& f, double a, double b, double fa, double fb, double tolerance,
                  int max_iterations) {
  double c = a, fc = fa, d = b - a, e = d;
  for (int it = 0; it < max_iterations; ++it) {
    if ((fb > 0.0) == (fc > 0.0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol = 2.0 * std::numeric_limits<double>::epsilon() * std::abs(b) + 0.5 * tolerance;
    const double m = 0.5 * (c - b);
    if (std::abs(m) <= tol || fb == 0.0) return b;
    if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb)) {
      double p, q;
      const double s = fb / fa;
      if (a == c) {
        p = 2.0 * m * s;
        q = 1.0 - s;
      } else {
        const double qa = fa / fc, r = fb / fc;
        p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
        q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0) q = -q;
      p = std::abs(p);
      if (2.0 * p < std::min(3.0 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = m;
        e = m;
      }
    } else {
      d = m;
      e = m;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol ? d : (m > 0.0 ? tol : -tol);
    fb = f(b);
  }
  return b;
}

}  // namespace fowtsim
