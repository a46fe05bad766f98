// The full-field evaluation: bilinear in y–z, linear in time, Taylor's shift and periodic wrap,
// tower points, and errors outside the box.
#include <array>
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "fowtsim/core/error.hpp"
#include "fowtsim/wind/wind_field.hpp"

using namespace fowtsim;
using namespace fowtsim::wind;

namespace {

// u = 10 + 0.05 y + 0.02 (z − 80) + 0.3 t', v = −0.01 y, w = 0.2 t' (t' the grid's own time):
// linear in y, z and t, so bilinear/linear interpolation must reproduce it (to float32 storage).
FullField linear_field(bool periodic) {
  FullField f;
  f.ny = 5;
  f.nz = 4;
  f.n_tower = 3;
  f.nt = 11;
  f.dy_m = 10.0;
  f.dz_m = 8.0;
  f.dt_s = 0.5;
  f.z_bottom_m = 80.0;
  f.z_hub_m = 92.0;
  f.u_hub_m_s = 10.0;
  f.periodic = periodic;
  for (int it = 0; it < f.nt; ++it) {
    const double t = it * f.dt_s;
    for (int iz = 0; iz < f.nz; ++iz)
      for (int iy = 0; iy < f.ny; ++iy) {
        const double y = -20.0 + iy * f.dy_m, z = f.z_bottom_m + iz * f.dz_m;
        f.grid.push_back(static_cast<float>(10.0 + 0.05 * y + 0.02 * (z - 80.0) + 0.3 * t));
        f.grid.push_back(static_cast<float>(-0.01 * y));
        f.grid.push_back(static_cast<float>(0.2 * t));
      }
    for (int k = 0; k < f.n_tower; ++k) {  // tower at z = 80, 72, 64 m
      f.tower.push_back(static_cast<float>(9.0 - k));
      f.tower.push_back(0.0f);
      f.tower.push_back(static_cast<float>(0.1 * k));
    }
  }
  return f;
}

Vec3 exact(double y, double z, double t_grid) {
  return Vec3(10.0 + 0.05 * y + 0.02 * (z - 80.0) + 0.3 * t_grid, -0.01 * y, 0.2 * t_grid);
}

}  // namespace

// Intent: at off-grid points and times, the value equals the linear field at the shifted time
// t' = t + (X0 − x)/U, X0 = half width (non-periodic, InflowWind); tolerance 1e-5 m/s (float32
// storage of values ~12 m/s: 7e-7, a few of them combined).
TEST_CASE("full-field interpolation is exact for a field linear in y, z and t", "[verification][wind]") {
  const FullField f = linear_field(false);
  for (const Vec3& p : {Vec3(0, 0, 92), Vec3(-7.5, 13.3, 97.1), Vec3(12.0, -19.9, 80.2), Vec3(3.0, 20.0, 104.0)})
    for (double t : {-0.7, 0.0, 0.37, 1.5, 2.2}) {
      const double t_grid = t + (20.0 - p.x()) / 10.0;
      CHECK((full_field_velocity(f, p, t) - exact(p.y(), p.z(), t_grid)).norm() < 1e-5);
    }
  // Record exhausted: t' beyond (nt − 1) dt = 5 s, or before 0.
  CHECK_THROWS_AS(full_field_velocity(f, Vec3(0, 0, 90), 3.1), NumericalError);
  CHECK_THROWS_AS(full_field_velocity(f, Vec3(0, 0, 90), -2.1), NumericalError);
  // Outside the grid laterally or above it.
  CHECK_THROWS_AS(full_field_velocity(f, Vec3(0, 20.5, 90), 0.0), NumericalError);
  CHECK_THROWS_AS(full_field_velocity(f, Vec3(0, 0, 104.5), 0.0), NumericalError);
}

// Intent: a periodic field starts at the hub (X0 = 0) and wraps with period nt·dt, the last
// sample interpolating linearly back to the first.
TEST_CASE("a periodic full field wraps with period nt*dt", "[unit][wind]") {
  const FullField f = linear_field(true);
  const double period = f.nt * f.dt_s;
  const Vec3 p(-4.0, 3.0, 90.0);
  CHECK((full_field_velocity(f, p, 0.8) - full_field_velocity(f, p, 0.8 + 3 * period)).norm() < 1e-12);
  CHECK((full_field_velocity(f, p, 0.8) - exact(3.0, 90.0, 0.8 + 0.4)).norm() < 1e-5);
  // Between the last sample (t = 5 s) and the wrap (t = 5.5 s = sample 0): halfway is the mean.
  const Vec3 mid = full_field_velocity(f, Vec3(0, 3.0, 90.0), 5.25);
  CHECK((mid - 0.5 * (exact(3.0, 90.0, 5.0) + exact(3.0, 90.0, 0.0))).norm() < 1e-5);
}

// Intent: below the grid the tower points (y = 0, z_bottom − k dz) are interpolated in z, then
// linearly to zero at the ground; without tower points the query is an error.
TEST_CASE("below the grid the tower points are used, down to zero at the ground", "[unit][wind]") {
  FullField f = linear_field(false);
  const double t = 1.0 - 2.0;  // t' = t + 20/10 = 1 s at x = 0 (values constant in time here)
  CHECK(full_field_velocity(f, Vec3(0, 0, 76.0), t).x() == Approx(8.5).epsilon(1e-6));  // halfway 80/72 m
  CHECK(full_field_velocity(f, Vec3(0, 0, 32.0), t).x() == Approx(7.0 * 32.0 / 64.0).epsilon(1e-6));
  CHECK(full_field_velocity(f, Vec3(0, 0, 32.0), t).z() == Approx(0.2 * 32.0 / 64.0).epsilon(1e-6));
  f.n_tower = 0;
  f.tower.clear();
  CHECK_THROWS_AS(full_field_velocity(f, Vec3(0, 0, 76.0), t), NumericalError);
}

TEST_CASE("inconsistent full fields are rejected", "[unit][wind]") {
  FullField f = linear_field(false);
  f.grid.pop_back();
  CHECK_THROWS_AS(validate(f), InputError);
  WindParams p;
  p.model = WindModel::bts;
  p.file = "x.bts";
  CHECK_THROWS_AS(WindField(p, std::make_shared<const FullField>(f)), InputError);
  CHECK_THROWS_AS(WindField(p), InputError);  // no field given
}

// Intent (issue 12 item 3): a deflected tip or a displaced platform beyond the grid's edge is not
// a stop: the wind field answers with the mean profile u_hub (z/z_hub)^α there and counts it.
TEST_CASE("a wind field answers points beyond the grid with the mean profile", "[unit][wind]") {
  WindParams params;
  params.model = WindModel::bts;
  params.file = "synthetic.bts";
  params.shear_exponent = 0.2;
  params.reference_height_m = 92.0;
  const WindField field(params, std::make_shared<const FullField>(linear_field(false)));
  CHECK(field.outside_queries() == 0);
  CHECK((field.velocity(Vec3(0, 13.3, 97.1), 0.37) - full_field_velocity(linear_field(false), Vec3(0, 13.3, 97.1), 0.37))
            .norm() < 1e-12);
  CHECK(field.outside_queries() == 0);
  for (const Vec3& p : {Vec3(0, 20.5, 90), Vec3(0, -25, 60), Vec3(0, 0, 110)}) {
    const Vec3 v = field.velocity(p, 0.37);
    CHECK(v.x() == Approx(10.0 * std::pow(p.z() / 92.0, 0.2)).epsilon(1e-14));
    CHECK(v.y() == 0.0);
    CHECK(v.z() == 0.0);
  }
  CHECK(field.outside_queries() == 3);
}

// Intent: the tower's foot lies below the grid by design (the tower drag's stations): those points
// take the same mean profile without being counted; a point beside the grid still is.
TEST_CASE("points below the grid asked for as such take the profile uncounted", "[unit][wind]") {
  WindParams params;
  params.model = WindModel::bts;
  params.file = "synthetic.bts";
  params.shear_exponent = 0.2;
  params.reference_height_m = 92.0;
  FullField f = linear_field(false);
  f.n_tower = 0;  // no tower column: below the grid only the profile is known
  f.tower.clear();
  const WindField field(params, std::make_shared<const FullField>(f));
  const std::array<Vec3, 2> points = {Vec3(0, 0, f.z_bottom_m - 5.0), Vec3(0, 0, 97.1)};
  std::array<Vec3, 2> v;
  field.velocities_profile_below(points, 0.37, v);
  CHECK(v[0].x() == Approx(10.0 * std::pow(points[0].z() / 92.0, 0.2)).epsilon(1e-14));
  CHECK((v[1] - field.velocity(points[1], 0.37)).norm() == 0.0);
  CHECK(field.outside_queries() == 0);
  const std::array<Vec3, 1> beside = {Vec3(0, 40.0, 90.0)};
  std::array<Vec3, 1> w;
  field.velocities_profile_below(beside, 0.37, w);
  CHECK(field.outside_queries() == 1);
}
