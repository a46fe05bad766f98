// OpenFAST uniform wind files (InflowWind WindType 2): the reader, the interpolation in time and
// each term of InflowWind's formula against hand values, and bad files stopping at file:line.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>

#include "fowtsim/core/error.hpp"
#include "fowtsim/wind/uniform_wind_file.hpp"
#include "fowtsim/wind/wind_field.hpp"

using namespace fowtsim;
using namespace fowtsim::wind;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// A uniform-file wind: RefHt 90 m, RefLength 126 m.
WindField uniform_field(const std::string& text, double direction_deg = 0.0) {
  WindParams p;
  p.model = WindModel::uniform_file;
  p.reference_height_m = 90.0;
  p.reference_length_m = 126.0;
  p.direction_deg = direction_deg;
  p.uniform = parse_uniform_wind(text, "test.hh");
  return WindField(p);
}

// Hand values are sums and products of a few decimals and the cos/sin of the turns: they differ
// from the module's by rounding only (every check passes at 4e-15, fails at 2e-15, relative and in
// m/s for the components that are zero, e.g. 10 cos 90° after two rotations); 4e-14 is 10× that.
void check_velocity(const Vec3& actual, const Vec3& expected) {
  for (int c = 0; c < 3; ++c) CHECK(actual[c] == Approx(expected[c]).epsilon(4e-14).margin(4e-14));
}

}  // namespace

// Intent: two rows, 0 s and 10 s, interpolated at 4 s (weight 0.4) column by column; the rows are
// held before the first and after the last time (InflowWind's rule); comment and blank lines
// skipped with the line numbers kept.
TEST_CASE("uniform wind files interpolate linearly in time", "[verification][wind][uniform]") {
  const std::string text =
      "! OpenFAST uniform wind file\n"
      "! Time Wind Wind Vert. Horiz. Pwr.Law Lin.Vert. Gust Upflow\n"
      "\n"
      "  0.0  10.0  0.0  0.0  0.0  0.0  0.0  0.0  0.0\n"
      " 10.0  20.0 10.0  1.0  0.5  0.2  0.25 2.0  5.0\r\n";
  const UniformWindHistory h = parse_uniform_wind(text, "test.hh");
  REQUIRE(h.rows.size() == 2);
  CHECK(h.lines == std::vector<std::size_t>{4, 5});
  const UniformWindRow r = uniform_wind_at(h, 4.0);
  CHECK(r.speed_m_s == Approx(14.0).epsilon(1e-15));
  CHECK(r.direction_rad == Approx(4.0 * kDeg).epsilon(1e-15));
  CHECK(r.vertical_m_s == Approx(0.4).epsilon(1e-15));
  CHECK(r.horizontal_shear == Approx(0.2).epsilon(1e-15));
  CHECK(r.power_law_exponent == Approx(0.08).epsilon(1e-15));
  CHECK(r.vertical_linear_shear == Approx(0.1).epsilon(1e-15));
  CHECK(r.gust_m_s == Approx(0.8).epsilon(1e-15));
  CHECK(r.upflow_rad == Approx(2.0 * kDeg).epsilon(1e-15));
  CHECK(uniform_wind_at(h, -3.0).speed_m_s == 10.0);
  CHECK(uniform_wind_at(h, 99.0).speed_m_s == 20.0);
  // The whole formula at a point off every axis, 4 s: V1 = 14 [(120/90)^0.08 + (0.2 (−20 cos 4° + 30 sin 4°)
  // + 0.1 · 30) / 126] + 0.8, turned by upflow 2° with V_z = 0.4, then by δ = 4°.
  const WindField field = uniform_field(text);
  const double d = 4.0 * kDeg, u = 2.0 * kDeg;
  const double v1 = 14.0 * (std::pow(120.0 / 90.0, 0.08) + (0.2 * (-20.0 * std::cos(d) + 30.0 * std::sin(d)) + 0.1 * 30.0) / 126.0) + 0.8;
  const double along = std::cos(u) * v1 - std::sin(u) * 0.4;
  check_velocity(field.velocity(Vec3(30.0, -20.0, 120.0), 4.0),
                 Vec3(along * std::cos(d), -along * std::sin(d), std::sin(u) * v1 + std::cos(u) * 0.4));
}

// Intent: each shear term on its own against hand values at the rotor disk's edge (RefLength 126 m,
// 63 m off the hub): horizontal linear H = 0.2 → V (1 + 0.2 · 63/126) = 1.1 V on the +y side;
// power law α = 0.2 at z = 45 m → V 0.5^0.2; linear vertical L = 0.3 at the top → 1.15 V; gust 3 m/s
// everywhere; direction 90° blows towards −y; an 8-column file has no upflow.
TEST_CASE("each term of InflowWind's uniform wind formula", "[verification][wind][uniform]") {
  check_velocity(uniform_field("0 10 0 0 0.2 0 0 0\n").velocity(Vec3(0, 63, 90), 1.0), Vec3(11.0, 0, 0));
  check_velocity(uniform_field("0 10 0 0 0.2 0 0 0\n").velocity(Vec3(0, -63, 90), 1.0), Vec3(9.0, 0, 0));
  check_velocity(uniform_field("0 10 0 0 0 0.2 0 0\n").velocity(Vec3(5, 7, 45), 1.0), Vec3(10.0 * std::pow(0.5, 0.2), 0, 0));
  check_velocity(uniform_field("0 10 0 0 0 0 0.3 0\n").velocity(Vec3(0, 0, 153), 1.0), Vec3(11.5, 0, 0));
  check_velocity(uniform_field("0 10 0 0 0 0 0 3\n").velocity(Vec3(-4, 9, 30), 1.0), Vec3(13.0, 0, 0));
  check_velocity(uniform_field("0 10 90 0.5 0 0 0 0\n").velocity(Vec3(0, 0, 90), 1.0), Vec3(0, -10.0, 0.5));
  // Horizontal shear follows the file's direction: with δ = 90° the lateral coordinate is +x.
  check_velocity(uniform_field("0 10 90 0 0.2 0 0 0\n").velocity(Vec3(63, 0, 90), 1.0), Vec3(0, -11.0, 0));
  // The deck's direction turns the box about (0, 0, RefHt) on top of the file's (InflowWind's PropagationDir).
  check_velocity(uniform_field("0 10 30 0 0 0 0 0\n", 60.0).velocity(Vec3(0, 0, 90), 1.0), Vec3(0, -10.0, 0));
  check_velocity(uniform_field("0 10 0 0 0 0 0 0\n").velocity(Vec3(0, 0, -1), 1.0), Vec3::Zero());  // below SWL
}

// Intent: directions are unwrapped as InflowWind does (within 180° of the previous row), so 350° →
// 10° turns through north: 0° (= 360°) halfway.
TEST_CASE("uniform wind directions take the short way round", "[unit][wind][uniform]") {
  const UniformWindHistory h = parse_uniform_wind("0 10 350 0 0 0 0 0\n10 10 10 0 0 0 0 0\n", "test.hh");
  CHECK(uniform_wind_at(h, 5.0).direction_rad == Approx(360.0 * kDeg).epsilon(1e-15));
}

// Intent: a malformed file stops before the run, naming file:line and what was expected.
TEST_CASE("bad uniform wind files stop at file:line", "[unit][wind][uniform]") {
  CHECK_THROWS_WITH(parse_uniform_wind("! header\n0 10 0 0 0 0 0\n", "a.hh"),
                    Catch::Contains("a.hh:2: expected 8 or 9 numbers"));
  CHECK_THROWS_WITH(parse_uniform_wind("0 10 0 0 0 0 0 0\n1 10 0 0 0 0 0 0 0\n", "a.hh"),
                    Catch::Contains("a.hh:2: expected 8 numbers as in the first data row (line 1)"));
  CHECK_THROWS_WITH(parse_uniform_wind("0 10 0 0 0 0 0 0\n1 1O 0 0 0 0 0 0\n", "a.hh"),
                    Catch::Contains("a.hh:2: cannot read '1O' as a horizontal speed [m/s]"));
  CHECK_THROWS_WITH(parse_uniform_wind("0 10 0 0 0 0 0 0\n\n0 10 0 0 0 0 0 0\n", "a.hh"),
                    Catch::Contains("a.hh:3: time 0 s is not after the previous row's"));
  CHECK_THROWS_WITH(parse_uniform_wind("0 10 0 0 0 0 0 0\n1 10 180 0 0 0 0 0\n", "a.hh"),
                    Catch::Contains("a.hh:2: the direction jumps by 180°"));
  CHECK_THROWS_WITH(parse_uniform_wind("0 nan 0 0 0 0 0 0\n", "a.hh"), Catch::Contains("a.hh:1:") && Catch::Contains("not finite"));
  CHECK_THROWS_WITH(parse_uniform_wind("! only a comment\n\n", "a.hh"), Catch::Contains("a.hh: no data rows"));
  CHECK_THROWS_WITH(read_uniform_wind_file("/nonexistent/x.hh"), Catch::Contains("cannot open"));
  WindParams p;
  p.model = WindModel::uniform_file;
  p.uniform = parse_uniform_wind("0 10 0 0 0 0 0 0\n", "a.hh");
  CHECK_THROWS_WITH(validate(p), Catch::Contains("wind.reference_length_m"));
  p.reference_length_m = 126.0;
  p.event.type = WindEventType::EOG;
  p.event.rotor_diameter_m = 126.0;
  p.speed_m_s = 10.0;
  CHECK_THROWS_WITH(validate(p), Catch::Contains("cannot be superposed on a uniform wind file"));
}
