// Velocity lookups are called every step for every aero node: they must not touch the heap.
#include <catch2/catch.hpp>

#include <memory>

#include "fowtsim/testing/allocation_counter.hpp"
#include "fowtsim/wind/wind_field.hpp"

using fowtsim::testing::allocations;
using fowtsim::testing::counting;
using namespace fowtsim;
using namespace fowtsim::wind;

TEST_CASE("wind velocity lookups allocate nothing", "[unit][wind]") {
  auto f = std::make_shared<FullField>();
  f->ny = 3;
  f->nz = 3;
  f->nt = 4;
  f->dy_m = f->dz_m = 10.0;
  f->dt_s = 1.0;
  f->z_bottom_m = 80.0;
  f->z_hub_m = 90.0;
  f->u_hub_m_s = 10.0;
  f->periodic = true;
  f->grid.assign(3 * 3 * 4 * 3, 7.0f);
  WindParams turbulent;
  turbulent.model = WindModel::bts;
  turbulent.file = "in-memory";
  const WindField grid_field(turbulent, f);
  WindParams shear;
  shear.model = WindModel::power_law;
  shear.speed_m_s = 10.0;
  shear.direction_deg = 10.0;
  const WindField profile(shear);
  WindParams gusty = shear;  // an event turning the inflow (ECD: speed and direction) rebuilds R each call
  gusty.event.type = WindEventType::ECD;
  gusty.event.rotor_diameter_m = 126.0;
  const WindField event(gusty);
  WindParams from_file = shear;
  from_file.model = WindModel::uniform_file;
  from_file.reference_length_m = 126.0;
  from_file.uniform = parse_uniform_wind("0 10 0 0 0.1 0.2 0.1 0\n5 12 10 0 0.1 0.2 0.1 1\n", "in-memory.hh");
  const WindField uniform(from_file);
  std::vector<Vec3> points(20, Vec3(1.0, 2.0, 91.0)), out(20);
  allocations = 0;
  counting = true;
  double sum = 0.0;
  for (int k = 0; k < 100; ++k) {
    grid_field.velocities(points, 0.1 * k, out);
    sum += out[0].x() + profile.velocity(Vec3(0, 0, 50.0 + k), 0.1 * k).x();
    event.velocities(points, 0.1 * k, out);
    sum += out[0].x() + uniform.velocity(Vec3(0, 0, 50.0 + k), 0.1 * k).x();
  }
  counting = false;
  CHECK(allocations == 0);
  CHECK(sum > 0.0);
}
