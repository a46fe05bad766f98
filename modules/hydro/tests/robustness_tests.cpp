// Poses far outside normal operation give finite, physical answers; bad inputs give clear errors.
#include <cmath>
#include <limits>
#include <numbers>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation.hpp"
#include "fowtsim/core/rotation_vector.hpp"
#include "fowtsim/hydro/benchmarks.hpp"
#include "fowtsim/hydro/oc3.hpp"
#include "test_members.hpp"

using namespace fowtsim;
using namespace fowtsim::hydro;

namespace {
constexpr double kPi = std::numbers::pi;

Hydro::Output oc3_in_wave(const Params& p, const Vec3& position, const Vec3& angles, double t) {
  FrameMotion pose;
  pose.position_m = position;
  pose.orientation = euler123_to_matrix(angles);
  pose.velocity_m_s = Vec3(0.5, -0.2, 0.3);
  pose.angular_velocity_rad_s = Vec3(0.01, 0.02, -0.03);
  const benchmarks::DeepWaterAiry wave{5.0, 12.0};
  return Hydro::outputs(p, test::input_at(p, pose, [&](const Points& pts, Hydro::Input& in) {
    benchmarks::fill_kinematics(wave, t, pts, in);
  }), {});
}
}  // namespace

TEST_CASE("OC3 spar at extreme poses: finite loads, volume within [0, V_total]", "[verification][hydro]") {
  // Intent: large offsets, 30–180° rotations, partly lifted out, fully lifted out, fully
  // submerged (the top at 10 m goes under at heave −10 m).
  const Params p = oc3_hywind_params();
  const double v_total = 8029.2092002162 + kPi / 4 * 6.5 * 6.5 * 10.0;  // geometry incl. the 10 m freeboard
  const struct {
    Vec3 position, angles;
  } poses[] = {{Vec3(5000.0, -3000.0, 0.0), Vec3::Zero()},
               {Vec3::Zero(), Vec3(0.0, kPi / 6, 0.0)},
               {Vec3(0, 0, 60.0), Vec3(0.2, 0.3, 0.0)},    // half out of the water
               {Vec3(0, 0, 200.0), Vec3::Zero()},          // lifted out
               {Vec3(0, 0, -50.0), Vec3::Zero()},          // fully submerged
               {Vec3(0, 0, -50.0), Vec3(0.0, kPi / 2, 0.0)},
               {Vec3(10, 0, 0.0), Vec3(kPi, 0.0, 0.0)},    // upside down
               {Vec3(0, 0, 0.0), Vec3(1.0, -1.2, 2.5)}};
  for (const auto& pose : poses) {
    const Hydro::Output out = oc3_in_wave(p, pose.position, pose.angles, 3.0);
    INFO("pose " << pose.position.transpose() << " / " << pose.angles.transpose());
    CHECK(out.total.allFinite());
    CHECK(out.added_mass.allFinite());
    CHECK(out.submerged_volume_m3 >= 0.0);
    CHECK(out.submerged_volume_m3 <= v_total * (1 + 1e-12));
  }
  const Hydro::Output out_of_water = oc3_in_wave(p, Vec3(0, 0, 200.0), Vec3::Zero(), 3.0);
  CHECK(out_of_water.buoyancy.norm() == 0.0);
  CHECK(out_of_water.morison.norm() == 0.0);
  CHECK(out_of_water.added_mass.norm() == 0.0);
  const Hydro::Output under = oc3_in_wave(p, Vec3(0, 0, -50.0), Vec3::Zero(), 3.0);
  CHECK(under.submerged_volume_m3 == Approx(v_total).epsilon(1e-12));
}

TEST_CASE("non-finite inputs raise NumericalError naming the quantity", "[unit][hydro]") {
  // Intent: never a NaN out.
  const Params p = oc3_hywind_params();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Hydro::Input in = make_input(p);
  in.platform.position_m.x() = nan;
  CHECK_THROWS_AS(Hydro::outputs(p, in, {}), NumericalError);
  in = make_input(p);
  in.fluid_velocity_m_s(0, 3) = nan;  // a wet strip node
  CHECK_THROWS_WITH(Hydro::outputs(p, in, {}), Catch::Contains("strip node 3"));
  in = make_input(p);
  in.platform.orientation(0, 0) = 2.0;
  CHECK_THROWS_WITH(Hydro::outputs(p, in, {}), Catch::Contains("not a rotation"));
  // Kinematics of dry nodes are not read (the driver may leave them undefined above the surface).
  in = make_input(p);
  in.fluid_velocity_m_s(0, node_count(p) - 1) = nan;  // end B of the top member, 10 m above SWL
  CHECK(Hydro::outputs(p, in, {}).total.allFinite());
  in = make_input(p);
  in.dynamic_pressure_Pa.resize(3);
  CHECK_THROWS_WITH(Hydro::outputs(p, in, {}), Catch::Contains("node_count"));
}

TEST_CASE("added linear terms: OC3 yaw spring and damping", "[unit][hydro]") {
  // Intent: F = F0 − C q − B q̇ with q from Euler 1-2-3 angles, q̇ rotational = ω in g.
  Params p = oc3_hywind_params();
  p.added_force[0] = 1e5;
  Hydro::Input in = make_input(p);
  in.platform.orientation = euler123_to_matrix(Vec3(0.0, 0.0, 0.1));
  in.platform.velocity_m_s = Vec3(0.2, 0.0, -0.1);
  in.platform.angular_velocity_rad_s = Vec3(0.0, 0.0, 0.05);
  const Vec6 f = Hydro::outputs(p, in, {}).added_linear;
  CHECK(f[0] == Approx(1e5 - 1e5 * 0.2).epsilon(1e-14));
  CHECK(f[2] == Approx(1.3e5 * 0.1).epsilon(1e-14));
  CHECK(f[5] == Approx(-9.834e7 * 0.1 - 1.3e7 * 0.05).epsilon(1e-13));
}

TEST_CASE("added linear terms at 30 deg pitch and yaw together: the true angular velocity, the Euler angles", "[unit][hydro]") {
  // Intent (DESIGN §3, large angles exact): the damping acts on ω in g, not on the Euler angle
  // rates, which differ from it once two angles are large; the stiffness acts on the Euler 1-2-3
  // angles as OpenFAST's AddCLin does on PtfmRoll/Pitch/Yaw.
  Params p = oc3_hywind_params();
  p.added_damping(3, 3) = p.added_damping(4, 4) = 2e6;  // roll and pitch damping too, to see every axis
  Hydro::Input in = make_input(p);
  const double deg = std::numbers::pi / 180.0;
  const Vec3 angles(0.0, 30.0 * deg, 30.0 * deg);
  in.platform.orientation = euler123_to_matrix(angles);
  in.platform.angular_velocity_rad_s = Vec3(0.02, -0.01, 0.05);  // body frame
  const Vec3 omega_g = in.platform.orientation * in.platform.angular_velocity_rad_s;
  const Vec6 f = Hydro::outputs(p, in, {}).added_linear;
  CHECK(f[3] == Approx(-2e6 * omega_g.x()).epsilon(1e-13));
  CHECK(f[4] == Approx(-2e6 * omega_g.y()).epsilon(1e-13));
  CHECK(f[5] == Approx(-9.834e7 * 30.0 * deg - 1.3e7 * omega_g.z()).epsilon(1e-13));
  // The Euler rates of the same motion (finite difference of the angles, 1e-7 s: truncation
  // ~1e-9 relative) differ from ω_g by more than 10 % here, so the check above tells them apart.
  const double h = 1e-7;
  const Mat3 later = in.platform.orientation * rotation_matrix(Vec3(h * in.platform.angular_velocity_rad_s));
  const Vec3 euler_rates = (matrix_to_euler123(later) - angles) / h;
  CHECK(std::abs(euler_rates.z() - omega_g.z()) > 0.1 * std::abs(omega_g.z()));
}

