// Seed paper Sec. 5.1: the uniform clamped-free beam (L 100 m, EI 2e12 N m², m 9e3 kg/m) with the
// single shape u_0 = 1 − cos(πx/2L), whose integrals have closed forms. Default quadrature: its
// error is below 1e-14 relative here (a smooth trigonometric integrand, 64 Gauss points), so the
// tolerances are rounding, 1e-12.
#include "fowtsim/flexbody/integrals.hpp"

#include <catch2/catch.hpp>

#include <numbers>

using namespace fowtsim::flexbody;
using std::numbers::pi;

TEST_CASE("Sec. 5.1 closed forms: M_q, K_q, top-mass and self-weight geometric stiffness", "[verification]") {
  const double L = 100.0, EI = 2e12, m = 9e3, g = 9.81, Mt = 3.5e5, M = m * L;
  const auto stations = uniform_beam(L, m, EI);
  const auto body = sample(quadrature_points(stations), {cosine_shape(L)});
  const double Kq = generalized_stiffness(body)(0, 0);
  const double Pcr = pi * pi * EI / (4 * L * L);  // massless-beam buckling load (Sec. 5.1)

  CHECK(generalized_mass(body)(0, 0) == Approx(m * L * (3 * pi - 8) / (2 * pi)).epsilon(1e-12));
  CHECK(Kq == Approx(EI * pi * pi * pi * pi / (32 * L * L * L)).epsilon(1e-12));
  // K_MT^T / K_q = −M_t g / P_cr (eq. 26 with T = −M_t g).
  const double KMT = geometric_stiffness(body, top_mass_axial_force(Mt, g))(0, 0);
  CHECK(KMT == Approx(-Mt * g * pi * pi / (8 * L)).epsilon(1e-12));
  CHECK(KMT / Kq == Approx(-Mt * g / Pcr).epsilon(1e-12));
  // K_SW^T = Mg(−π²/(8L) + (4 + π²)/(16L)), K_SW^T / K_q = −(Mg/P_cr)(1/2 − 2/π²).
  const double KSW = geometric_stiffness(body, self_weight_axial_force(stations, g))(0, 0);
  CHECK(KSW == Approx(M * g * (-pi * pi / (8 * L) + (4 + pi * pi) / (16 * L))).epsilon(1e-12));
  CHECK(KSW / Kq == Approx(-(M * g / Pcr) * (0.5 - 2 / (pi * pi))).epsilon(1e-12));
  // Centrifugal (Sec. 5.2), T = Ω² m [(L² − x²)/2 + r (L − x)]: ∫ T ν_0² dx
  // = Ω² m [L(π²/24 − 1/8) + r(π²/16 − 1/4)] (∫_0^1 (1 − t²) sin²(πt/2) dt = 1/3 − 1/π²).
  const double Omega = 1.2, r = 3.0;
  CHECK(geometric_stiffness(body, centrifugal_axial_force(stations, Omega, r))(0, 0) ==
        Approx(Omega * Omega * m * (L * (pi * pi / 24 - 0.125) + r * (pi * pi / 16 - 0.25))).epsilon(1e-12));
  // First moments: ∫ m u_0 = mL(1 − 2/π); ∫ m x u_0 = mL² ∫_0^1 t(1 − cos(πt/2)) dt
  // = mL²(1/2 − 2/π + 4/π²), by parts.
  CHECK(mass_first_moment(body)(0) == Approx(m * L * (1 - 2 / pi)).epsilon(1e-12));
  CHECK(mass_axial_moment(body)(0) == Approx(m * L * L * (0.5 - 2 / pi + 4 / (pi * pi))).epsilon(1e-12));
}
