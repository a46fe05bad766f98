#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include "fowtsim/core/interface.hpp"
#include "fowtsim/core/rotation.hpp"

using namespace fowtsim;

TEST_CASE("frame motion interpolation hits both ends and keeps a rotation", "[unit][interface]") {
  FrameMotion a, b;
  b.position_m = {2, 0, 0};
  b.acceleration_m_s2 = {0, 4, 0};
  b.orientation = euler123_to_matrix({0.0, 0.0, 1.0});
  const FrameMotion mid = interpolate(a, b, 0.5);
  CHECK((mid.position_m - Vec3(1, 0, 0)).norm() < 1e-15);
  CHECK((mid.acceleration_m_s2 - Vec3(0, 2, 0)).norm() < 1e-15);
  CHECK((mid.orientation - euler123_to_matrix({0.0, 0.0, 0.5})).norm() < 1e-14);  // slerp: half the angle
  CHECK((interpolate(a, b, 1.0).orientation - b.orientation).norm() < 1e-14);
}

TEST_CASE("root load averager returns the mean force, moment and point", "[unit][interface]") {
  LoadAverager<RootLoads> avg;
  CHECK_THROWS(avg.average());
  avg.add({{1, 0, 0}, {0, 0, 2}, {0, 0, 10}});
  avg.add({{3, 0, 0}, {0, 0, 4}, {0, 0, 12}});
  const RootLoads m = avg.average();
  CHECK(m.force_N.x() == 2.0);
  CHECK(m.moment_N_m.z() == 3.0);
  CHECK(m.point_m.z() == 11.0);
  avg.reset();
  CHECK(avg.total_weight() == 0.0);
  // Trapezoidal weights: samples 0, 2, 4 of a linear ramp average to its mean, 2.
  auto force_only = [](double fx) {  // moment and point stay zero (an Eigen `{}` would not initialise them)
    RootLoads r;
    r.force_N.x() = fx;
    return r;
  };
  avg.add(force_only(0.0), 0.5);
  avg.add(force_only(2.0), 1.0);
  avg.add(force_only(4.0), 0.5);
  CHECK(avg.average().force_N.x() == 2.0);
}
