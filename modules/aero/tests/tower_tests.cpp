// Tower influence against potential flow computed independently from the complex potential of a
// cylinder in a uniform stream, w(z) = U (z + R²/z), and hand values of the shadow and end taper.
#include <cmath>
#include <numbers>

#include <catch2/catch.hpp>

#include "fowtsim/aero/tower_influence.hpp"
#include "fowtsim/aero/verification.hpp"

using namespace fowtsim;
using namespace fowtsim::aero;

namespace {
// Vertical tower, base at the origin, 0…100 m, D = 6 m (R = 3 m), C_d = 1, TI = 0.1.
Params tower_params(TowerPotential potential, TowerShadow shadow) {
  Params p;
  p.tower_potential = potential;
  p.tower_shadow = shadow;
  p.tower = {{0.0, 6.0, 1.0, 0.1}, {100.0, 6.0, 1.0, 0.1}};
  return p;
}
const Vec3 kAxis = Vec3::UnitZ();
}  // namespace

// Intent: the baseline model is the exact 2-D potential flow: u − i v = U (1 − R²/z²) with z the
// position in the plane normal to the tower (wind along +x). Hand values: on the upstream axis at
// 2R, u = 0.75 U; abeam at 2R, u = 1.25 U; at (−2R, −2R), u = U, v = −U/8.
TEST_CASE("tower potential flow equals the cylinder's complex potential", "[verification][aero]") {
  const Params p = tower_params(TowerPotential::baseline, TowerShadow::none);
  const Vec3 wind(10.0, 0.0, 0.0);
  auto velocity = [&](double x, double y) -> Vec3 {
    return wind + tower_disturbance(p, Vec3::Zero(), kAxis, Vec3(x, y, 50.0), wind);
  };
  CHECK(velocity(-6.0, 0.0).x() == Approx(7.5).margin(1e-12));
  CHECK(velocity(0.0, 6.0).x() == Approx(12.5).margin(1e-12));
  const Vec3 oblique = velocity(-6.0, -6.0);
  CHECK(oblique.x() == Approx(10.0).margin(1e-12));
  CHECK(oblique.y() == Approx(-1.25).margin(1e-12));
  // The rings of verification::tower_potential_flow() against the complex potential, evaluated
  // independently there: round-off of the two forms only.
  const verification::PotentialFlowCheck rings = verification::tower_potential_flow();
  CHECK(rings.worst_m_s < 1e-12);
  CHECK(rings.points == 120);
}

// Intent: beyond the tower top the potential flow fades as cos²(π z̄/2) (z̄ in radii), and the
// disturbance is zero within 0.01 D of the surface and beyond 20 D.
TEST_CASE("tower influence end taper and exclusion zones", "[verification][aero]") {
  const Params p = tower_params(TowerPotential::baseline, TowerShadow::none);
  const Vec3 wind(10.0, 0.0, 0.0);
  const Vec3 full = tower_disturbance(p, Vec3::Zero(), kAxis, Vec3(-6.0, 0.0, 100.0), wind);
  const Vec3 half = tower_disturbance(p, Vec3::Zero(), kAxis, Vec3(-6.0, 0.0, 101.5), wind);  // z̄ = 0.5
  CHECK(full.x() == Approx(-2.5).margin(1e-12));
  CHECK(half.x() == Approx(-2.5 * 0.5).margin(1e-12));  // cos²(π/4) = 1/2
  CHECK(tower_disturbance(p, Vec3::Zero(), kAxis, Vec3(-6.0, 0.0, 103.0), wind).norm() == 0.0);
  CHECK(tower_disturbance(p, Vec3::Zero(), kAxis, Vec3(-3.05, 0.0, 50.0), wind).norm() == 0.0);
  CHECK(tower_disturbance(p, Vec3::Zero(), kAxis, Vec3(-130.0, 0.0, 50.0), wind).norm() == 0.0);
}

// Intent: Powles' deficit −C_d/√r̄ cos²(π ȳ/(2√r̄)) downstream only, zero outside the wake width,
// capped at half the speed; the Eames centreline deficit is −C_d/(TI x̄ √(2π)).
TEST_CASE("tower shadow deficits", "[verification][aero]") {
  const Vec3 wind(10.0, 0.0, 0.0);
  const Params powles = tower_params(TowerPotential::none, TowerShadow::powles);
  CHECK(tower_disturbance(powles, Vec3::Zero(), kAxis, Vec3(27.0, 0.0, 50.0), wind).x() ==
        Approx(-10.0 / 3.0).margin(1e-12));  // x̄ = 9: −1/3 of U
  CHECK(tower_disturbance(powles, Vec3::Zero(), kAxis, Vec3(-27.0, 0.0, 50.0), wind).norm() == 0.0);
  CHECK(tower_disturbance(powles, Vec3::Zero(), kAxis, Vec3(27.0, 10.0, 50.0), wind).norm() == 0.0);
  CHECK(tower_disturbance(powles, Vec3::Zero(), kAxis, Vec3(6.0, 0.0, 50.0), wind).x() ==
        Approx(-5.0).margin(1e-12));  // x̄ = 2: −1/√2 capped at −0.5
  const Params eames = tower_params(TowerPotential::none, TowerShadow::eames);
  CHECK(tower_disturbance(eames, Vec3::Zero(), kAxis, Vec3(60.0, 0.0, 50.0), wind).x() ==
        Approx(-10.0 / (0.1 * 20.0 * std::sqrt(2.0 * std::numbers::pi))).margin(1e-12));  // x̄ = 20
}
