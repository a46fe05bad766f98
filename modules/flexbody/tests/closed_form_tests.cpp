// Seed paper Sec. 5.1: the uniform clamped-free beam (L 100 m, EI 2e12 N m², m 9e3 kg/m) with the
// single shape u_0 = 1 − cos(πx/2L), whose integrals have closed forms (verification.hpp lists them;
// `fowtsim verify flexbody` runs the same computation). Default quadrature: its error is below
// 1e-14 relative here (a smooth trigonometric integrand, 64 Gauss points), so the tolerances are
// rounding, 1e-12.
#include "fowtsim/flexbody/verification.hpp"

#include <catch2/catch.hpp>

using namespace fowtsim::flexbody::verification;

TEST_CASE("Sec. 5.1 closed forms: M_q, K_q, top-mass and self-weight geometric stiffness", "[verification]") {
  // Top mass 3.5e5 kg, g 9.81; centrifugal (Sec. 5.2) at Ω 1.2 rad/s, root radius 3 m.
  const CosineBeam c = cosine_beam_closed_forms(3.5e5, 9.81, 1.2, 3.0);
  const Checked all[] = {c.Mq,          c.Kq,           c.top_mass,     c.top_mass_ratio, c.self_weight,
                         c.self_weight_ratio, c.centrifugal, c.first_moment, c.axial_moment};
  for (const Checked& k : all) CHECK(k.value == Approx(k.exact).epsilon(1e-12));
}
