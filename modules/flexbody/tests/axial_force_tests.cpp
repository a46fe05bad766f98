#include "fowtsim/flexbody/axial_force.hpp"

#include <catch2/catch.hpp>

using namespace fowtsim::flexbody;

TEST_CASE("Axial forces on a tapered table integrate linear m exactly from x to the tip", "[unit]") {
  // m = 3 − s/2 on [0, 4], 1 + (s − 4)/6 on [4, 10]. By hand at x = 2: ∫_2^10 m = 3 + 9 = 12,
  // ∫_2^10 m s ds = 26/3 + 66 = 224/3; at the tip both vanish. Tolerance: rounding.
  const BeamStations s{{0.0, 4.0, 10.0}, {3.0, 1.0, 2.0}, {1.0, 1.0, 1.0}};
  const double g = 9.81;
  CHECK(self_weight_axial_force(s, g)(2.0) == Approx(-g * 12.0).epsilon(1e-14));
  CHECK(self_weight_axial_force(s, g)(0.0) == Approx(-g * (8.0 + 9.0)).epsilon(1e-14));
  CHECK(self_weight_axial_force(s, g)(10.0) == 0.0);
  CHECK(centrifugal_axial_force(s, 1.0, 0.0)(2.0) == Approx(224.0 / 3.0).epsilon(1e-14));
  // Root radius r adds Ω² r ∫_x^L m: Ω = 2, r = 1.5.
  CHECK(centrifugal_axial_force(s, 2.0, 1.5)(2.0) == Approx(4.0 * (224.0 / 3.0 + 1.5 * 12.0)).epsilon(1e-14));
  CHECK(top_mass_axial_force(1000.0, g)(3.0) == -1000.0 * g);
}
