#pragma once
// Depth attenuation of one Airy component at level z (−h ≤ z ≤ 0), written so that neither deep
// water (cosh, sinh overflow beyond kh ≈ 710) nor shallow water (sinh kh → 0) loses digits:
//   cosh k(z+h)/sinh kh = e^{kz} (1 + e^{−2k(z+h)}) / (1 − e^{−2kh})
//   sinh k(z+h)/sinh kh = e^{kz} (1 − e^{−2k(z+h)}) / (1 − e^{−2kh})
//   cosh k(z+h)/cosh kh = e^{kz} (1 + e^{−2k(z+h)}) / (1 + e^{−2kh})
// with 1 − e^{−u} = −expm1(−u). h = +∞ gives e^{kz} for all three.
#include <cmath>

namespace fowtsim::waves::detail {

struct DepthFactors {
  double cosh_over_sinh = 0.0;  // F_cs: horizontal velocity and acceleration
  double sinh_over_sinh = 0.0;  // F_ss: vertical velocity and acceleration
  double cosh_over_cosh = 0.0;  // F_cc: dynamic pressure
};

inline DepthFactors depth_factors(double k, double z, double depth) {
  // Beyond an exponent of 40, e^{−u} < 5e-18 leaves 1 ± e^{−u} = 1 exactly in double: skip the
  // exponentials there (deep-water components), with bit-identical results.
  constexpr double kNegligible = 40.0;
  const double e = std::exp(k * z);
  const double u = 2.0 * k * (z + depth);           // +∞ in deep water
  const double bottom = u > kNegligible ? 0.0 : std::exp(-u);                 // e^{−2k(z+h)}
  const double one_minus_bottom = u > kNegligible ? 1.0 : -std::expm1(-u);    // 1 − e^{−2k(z+h)}
  const double v = 2.0 * k * depth;
  const double sinh_den = v > kNegligible ? 1.0 : -std::expm1(-v);            // 1 − e^{−2kh}
  const double cosh_den = v > kNegligible ? 1.0 : 1.0 + std::exp(-v);         // 1 + e^{−2kh}
  DepthFactors f;
  f.cosh_over_sinh = e * (1.0 + bottom) / sinh_den;
  f.sinh_over_sinh = e * one_minus_bottom / sinh_den;
  f.cosh_over_cosh = e * (1.0 + bottom) / cosh_den;
  return f;
}

}  // namespace fowtsim::waves::detail
