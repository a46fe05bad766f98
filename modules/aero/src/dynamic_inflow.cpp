#include "fowtsim/aero/dynamic_inflow.hpp"

#include <algorithm>
#include <cmath>

namespace fowtsim::aero {

double oye_tau1(double mean_axial_induction, double rotor_radius_m, double mean_inflow_m_s) {
  const double a = std::min(mean_axial_induction, 0.5);
  return 1.1 / (1.0 - 1.3 * a) * rotor_radius_m / mean_inflow_m_s;
}

double oye_tau2(double tau1_s, double radius_ratio) { return (0.39 - 0.26 * radius_ratio * radius_ratio) * tau1_s; }

// With λ1 = 1/τ1, λ2 = 1/τ2, s = (u1 − u0)/h and u(t) = u0 + s t:
//   z(t) = (1−k)(u − s/λ1) + C e^{−λ1 t},          C = z0 − (1−k)(u0 − s/λ1)
//   z + k u = p(t) + C e^{−λ1 t},                   p(t) = u(t) − (1−k) s/λ1
//   W(t) = p(t) − s/λ2 + D e^{−λ1 t} + E e^{−λ2 t},  D = λ2 C/(λ2 − λ1),  E = W0 − p(0) + s/λ2 − D.
void advance_oye(OyeFilter& f, double tau1_s, double tau2_s, double u0, double u1, double h) {
  const double l1 = 1.0 / tau1_s, l2 = 1.0 / tau2_s;
  const double s = (u1 - u0) / h;
  const double e1 = std::exp(-l1 * h), e2 = std::exp(-l2 * h);
  const double c = f.z - (1.0 - kOyeK) * (u0 - s / l1);
  const double p0 = u0 - (1.0 - kOyeK) * s / l1, p1 = u1 - (1.0 - kOyeK) * s / l1;
  const double d = l2 * c / (l2 - l1);
  const double e = f.w - p0 + s / l2 - d;
  f.z = (1.0 - kOyeK) * (u1 - s / l1) + c * e1;
  f.w = p1 - s / l2 + d * e1 + e * e2;
}

}  // namespace fowtsim::aero
