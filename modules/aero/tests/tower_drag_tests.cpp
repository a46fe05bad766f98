// Tower drag (AeroDyn TwrAero) against closed forms: a cylinder's drag ½ ρ C_d D U² per unit
// length, integrated over a tapered tower by hand.
#include <array>
#include <cmath>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include "fowtsim/aero/tower_drag.hpp"

using namespace fowtsim;
using namespace fowtsim::aero;

namespace {

// The OC3-Hywind tower's ends (AeroDyn TwrElev/TwrDiam: 10 m, 6.5 m → 87.6 m, 3.87 m), C_d = 1,
// tilted 5° about y (a pitched platform), base at (2, 0, −1) m.
struct Case {
  Params p;
  Vec3 base = Vec3(2.0, 0.0, -1.0);
  Vec3 axis = Vec3(std::sin(0.0872664626), 0.0, std::cos(0.0872664626));
  std::array<Vec3, 3> position, velocity, inflow;
  Case() {
    p.air_density_kg_m3 = 1.225;
    p.tower_drag = true;
    p.tower = {{10.0, 6.5, 1.0, 0.1}, {48.8, 5.185, 1.0, 0.1}, {87.6, 3.87, 1.0, 0.1}};
    tower_station_positions(p, base, axis, position);
    velocity.fill(Vec3::Zero());
  }
  TowerDragLoad load(const Vec3& about) const { return tower_drag(p, axis, position, velocity, inflow, about); }
};

}  // namespace

// Intent: wind U normal to the axis on a linearly tapered tower: F = ½ ρ C_d U² ∫D ds and the
// moment about the base F̄ × its lever ∫ s D ds / ∫ D ds along the axis — exact, since the load is
// linear between stations. Hand integrals over s ∈ [10, 87.6] with D(s) = 6.5 − (s − 10)·2.63/77.6.
TEST_CASE("tower drag of a uniform wind on a tapered tower equals the hand integral", "[unit][aero]") {
  Case c;
  const Vec3 normal = Vec3::UnitY();  // ⟂ to the tilted axis
  const double u = 12.0;
  c.inflow.fill(u * normal);
  const double s0 = 10.0, s1 = 87.6, d0 = 6.5, d1 = 3.87, slope = (d1 - d0) / (s1 - s0);
  const double integral_d = 0.5 * (d0 + d1) * (s1 - s0);
  // ∫ s D(s) ds = ∫ s (d0 + slope (s − s0)) ds
  auto primitive = [&](double s) { return d0 * s * s / 2.0 + slope * (s * s * s / 3.0 - s0 * s * s / 2.0); };
  const double integral_sd = primitive(s1) - primitive(s0);
  const double q = 0.5 * 1.225 * 1.0 * u * u;
  const TowerDragLoad load = c.load(c.base);
  // Sums of 10 products: a few roundings of 1e-16 each; 1e-14 leaves room.
  CHECK(load.force_N.y() == Approx(q * integral_d).epsilon(1e-14));
  CHECK(load.force_N.x() == Approx(0.0).margin(1e-9));  // N, against a force of 3e4 N: roundings only
  const Vec3 expected_moment = (integral_sd * c.axis).cross(q * normal);
  CHECK((load.moment_N_m - expected_moment).norm() < 1e-12 * expected_moment.norm());  // roundings of a cubic's integral
  // About another point: the same force, the moment shifted by (base − point) × F.
  const Vec3 point(-5.0, 3.0, 40.0);
  const TowerDragLoad moved = c.load(point);
  // The shift adds r × F of size 1e6 N·m to a moment of 1e6: cancellation leaves ~1e-15 relative; 1e-9 leaves room.
  CHECK((moved.moment_N_m - (load.moment_N_m + (c.base - point).cross(load.force_N))).norm() < 1e-9 * load.moment_N_m.norm());
}

// Intent: only the flow normal to the axis and relative to the tower drags: wind along the axis
// gives nothing, a tower moving with the wind nothing, and the drag grows with the square of the
// relative speed and opposes a tower moving through still air.
TEST_CASE("tower drag takes the relative flow normal to the axis, quadratic in its speed", "[unit][aero]") {
  Case c;
  // Wind along the tilted axis: what is left of it normal to the axis is rounding of |axis| = 1
  // (1e-16 × 7 m/s), a force below 1e-20 N where 1 m/s normal gives 3e3 N.
  c.inflow.fill(7.0 * c.axis);
  CHECK(c.load(c.base).force_N.norm() < 1e-12);
  c.inflow.fill(Vec3(10.0, 0.0, 0.0));
  c.velocity.fill(Vec3(10.0, 0.0, 0.0));
  CHECK(c.load(c.base).force_N.norm() == 0.0);  // the relative velocity is exactly zero
  c.velocity.fill(Vec3::Zero());
  const Vec3 at10 = c.load(c.base).force_N;
  c.inflow.fill(Vec3(20.0, 0.0, 0.0));
  CHECK(c.load(c.base).force_N.x() == Approx(4.0 * at10.x()).epsilon(1e-14));
  c.inflow.fill(Vec3::Zero());
  c.velocity.fill(Vec3(0.0, 2.0, 0.0));
  CHECK(c.load(c.base).force_N.y() < 0.0);
}

// Intent: the consistent nodal loads of a linear element, F_a = h (2 f_a + f_b)/6, F_b = h (f_a + 2 f_b)/6,
// carry the distributed drag's resultant and its first moment exactly (stations on a straight line):
// the flexible tower takes them as point loads instead of tower_drag()'s resultant. A sheared,
// turning wind with moving stations, so that f differs in size and direction from station to station.
TEST_CASE("tower drag as consistent nodal loads has the exact resultant and first moment", "[unit][aero]") {
  Case c;
  c.inflow = {Vec3(8.0, 1.0, 0.2), Vec3(11.0, -2.0, 0.0), Vec3(13.0, 3.5, -0.4)};
  c.velocity = {Vec3(0.1, 0.0, 0.0), Vec3(0.6, -0.3, 0.1), Vec3(1.2, 0.4, -0.2)};
  std::array<Vec3, 3> nodal;
  tower_drag_nodal(c.p, c.axis, c.velocity, c.inflow, nodal);
  const Vec3 about(-5.0, 3.0, 40.0);
  const TowerDragLoad exact = c.load(about);
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
  for (std::size_t i = 0; i < nodal.size(); ++i) {
    force += nodal[i];
    moment += (c.position[i] - about).cross(nodal[i]);
  }
  // Both are sums of a handful of products of size 1e4–1e6: roundings ~1e-16 each; 1e-12 leaves room.
  CHECK((force - exact.force_N).norm() < 1e-12 * exact.force_N.norm());
  CHECK((moment - exact.moment_N_m).norm() < 1e-12 * exact.moment_N_m.norm());
}
