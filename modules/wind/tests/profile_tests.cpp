// Steady, power-law and log winds against their closed forms; direction/upflow rotation;
// parameter validation; the module contract's channels.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/module.hpp"
#include "fowtsim/wind/wind_field.hpp"

using namespace fowtsim;
using namespace fowtsim::wind;

static_assert(Module<Wind>);

namespace {
WindParams analytic(WindModel model) {
  WindParams p;
  p.model = model;
  p.speed_m_s = 11.4;
  p.reference_height_m = 90.0;
  p.shear_exponent = 0.14;
  p.roughness_m = 0.0002;
  return p;
}
}  // namespace

// Intent: steady wind is the same vector at every point above SWL and every time, exactly.
TEST_CASE("steady wind is exact everywhere above the sea surface", "[verification][wind]") {
  const WindField field(analytic(WindModel::steady));
  for (const Vec3& p : {Vec3(0, 0, 90), Vec3(-60, 40, 10), Vec3(300, -80, 250)})
    for (double t : {0.0, 3.7, 1e4}) CHECK(field.velocity(p, t) == Vec3(11.4, 0.0, 0.0));  // exact: no arithmetic
  CHECK(field.velocity(Vec3(0, 0, -1), 0.0) == Vec3::Zero());
}

// Intent: U(z) = U_ref (z/z_ref)^α and U_ref ln(z/z0)/ln(z_ref/z0), against the closed form evaluated
// here independently; tolerance 1e-13 relative (double rounding of pow/log, a few ulp).
TEST_CASE("power-law and log shear match their closed forms", "[verification][wind]") {
  const WindField power(analytic(WindModel::power_law));
  const WindField log_law(analytic(WindModel::log));
  for (double z : {5.0, 27.5, 90.0, 152.5}) {
    const double expected_power = 11.4 * std::pow(z / 90.0, 0.14);
    const double expected_log = 11.4 * std::log(z / 0.0002) / std::log(90.0 / 0.0002);
    CHECK(power.velocity(Vec3(12.0, -30.0, z), 8.0).x() == Approx(expected_power).epsilon(1e-13));
    CHECK(log_law.velocity(Vec3(12.0, -30.0, z), 8.0).x() == Approx(expected_log).epsilon(1e-13));
  }
  CHECK(power.velocity(Vec3(0, 0, 90), 0).x() == 11.4);  // reference height: exactly U_ref
  CHECK(log_law.velocity(Vec3(0, 0, 0.0001), 0).x() == 0.0);  // below z0
}

// Intent: direction θ and upflow φ give u along (cos φ cos θ, −cos φ sin θ, sin φ) (InflowWind:
// PropagationDir positive rotates +x towards −y; upflow positive up); exact to 1e-14 m/s.
TEST_CASE("direction and upflow rotate the wind as InflowWind's angles", "[verification][wind]") {
  WindParams p = analytic(WindModel::steady);
  p.direction_deg = 30.0;
  p.upflow_deg = 8.0;
  const WindField field(p);
  const double th = 30.0 * std::numbers::pi / 180.0, ph = 8.0 * std::numbers::pi / 180.0;
  const Vec3 expected = 11.4 * Vec3(std::cos(ph) * std::cos(th), -std::cos(ph) * std::sin(th), std::sin(ph));
  CHECK((field.velocity(Vec3(0, 0, 90), 0.0) - expected).norm() < 1e-14);

  // With shear, the profile is evaluated at the wind-frame height of the point (box rotated about
  // the hub): a point 100 m upwind along the tilted flow line through the hub sees U_ref.
  WindParams q = analytic(WindModel::power_law);
  q.upflow_deg = 8.0;
  const WindField tilted(q);
  const Vec3 on_axis = Vec3(0, 0, 90) - 100.0 * Vec3(std::cos(ph), 0.0, std::sin(ph));
  CHECK((tilted.velocity(on_axis, 0.0) - 11.4 * Vec3(std::cos(ph), 0.0, std::sin(ph))).norm() < 1e-12);
}

TEST_CASE("bad wind parameters are rejected with the key", "[unit][wind]") {
  WindParams p = analytic(WindModel::power_law);
  p.shear_exponent = NAN;
  CHECK_THROWS_WITH(WindField(p), Catch::Contains("wind.shear_exponent"));
  p = analytic(WindModel::log);
  p.roughness_m = 100.0;
  CHECK_THROWS_WITH(WindField(p), Catch::Contains("wind.roughness_m"));
  p = analytic(WindModel::bts);
  CHECK_THROWS_WITH(WindField(p), Catch::Contains("wind.file"));
  p = analytic(WindModel::turbulent);
  p.turbulence.ny = 1;
  CHECK_THROWS_WITH(WindField(p), Catch::Contains("wind.turbulence.ny"));
  CHECK_THROWS_AS(parse_wind_model("uniform"), InputError);
  CHECK(parse_turbulence_category("C") == TurbulenceCategory::C);
  CHECK(parse_turbulence_model("ETM") == TurbulenceModel::ETM);
  CHECK(parse_turbulence_model("EWM") == TurbulenceModel::EWM);
  CHECK_THROWS_WITH(parse_turbulence_model("EWM50"), Catch::Contains("NTM, ETM, EWM"));
}

// Intent: the channels are OpenFAST's Wind1VelX/Y/Z at the probe point.
TEST_CASE("the wind module outputs Wind1VelX/Y/Z at the probe point", "[unit][wind]") {
  WindParams p = analytic(WindModel::power_law);
  p.probe_point_m = Vec3(0.0, 0.0, 45.0);
  const Wind::Params params{std::make_shared<const WindField>(p)};
  Wind::State s = Wind::make_state(params);
  Wind::advance(params, {}, 0.0, 0.05, s);
  CHECK(s.time_s == 0.05);
  const auto names = Wind::channels(params);
  REQUIRE(names.size() == 3);
  CHECK(names[0].name == "Wind1VelX");
  CHECK(names[2].unit == "m/s");
  CHECK(Wind::outputs(params, {}, s).probe_velocity_m_s.x() == Approx(11.4 * std::pow(0.5, 0.14)).epsilon(1e-14));
}
