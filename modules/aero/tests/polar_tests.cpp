// Airfoil polar lookup and the NREL 5MW deck as read from inputs/nrel5mw.
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/aero/polar.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/core/interpolation.hpp"
#include "fowtsim/core/spline.hpp"
#include "nrel5mw_deck.hpp"

using namespace fowtsim;
using namespace fowtsim::aero;

namespace {
constexpr double kDegree = std::numbers::pi / 180.0;

std::vector<double> full_circle(int n) {
  std::vector<double> a;
  for (int i = 0; i < n; ++i) a.push_back(-180.0 + 360.0 * i / (n - 1));
  return a;
}
}  // namespace

// Intent: both lookups pass through every table point of every NREL 5MW airfoil.
TEST_CASE("polar lookup reproduces the table points", "[unit][aero]") {
  const Params p = aero::testing::load_nrel5mw_deck();
  for (const Polar& polar : p.airfoils) {
    for (PolarInterpolation mode : {PolarInterpolation::linear, PolarInterpolation::cubic_spline}) {
      std::vector<double> deg;
      for (double a : polar.alpha_rad()) deg.push_back(a / kDegree);
      const Polar q(polar.name(), deg, polar.cl(), polar.cd(), polar.cm(), mode);
      for (std::size_t i = 0; i + 1 < deg.size(); ++i) {
        const AirfoilCoefficients c = q.evaluate(polar.alpha_rad()[i]);
        CHECK(c.cl == Approx(polar.cl()[i]).margin(1e-12));  // exact interpolant: round-off only
        CHECK(c.cd == Approx(polar.cd()[i]).margin(1e-12));
        CHECK(c.cm == Approx(polar.cm()[i]).margin(1e-12));
      }
    }
  }
}

// Intent: linear lookup is the chord between points; the natural spline is exact on linear data;
// angles wrap with period 2π.
TEST_CASE("polar interpolation between points and angle wrapping", "[unit][aero]") {
  const std::vector<double> alpha = full_circle(37);
  std::vector<double> cl, cd, cm;
  for (double a : alpha) {
    cl.push_back(0.01 * a);
    cd.push_back(1.0 + 0.002 * a);
    cm.push_back(-0.001 * a);
  }
  const Polar spline("linear-data", alpha, cl, cd, cm, PolarInterpolation::cubic_spline);
  const Polar linear("linear-data", alpha, cl, cd, cm, PolarInterpolation::linear);
  for (double a_deg : {-177.3, -95.0, -3.3, 0.0, 12.7, 179.9}) {
    const AirfoilCoefficients s = spline.evaluate(a_deg * kDegree);
    const AirfoilCoefficients l = linear.evaluate(a_deg * kDegree);
    CHECK(s.cl == Approx(0.01 * a_deg).margin(1e-12));  // linear data: spline is exact to round-off
    CHECK(l.cl == Approx(0.01 * a_deg).margin(1e-12));
    CHECK(s.cd == Approx(1.0 + 0.002 * a_deg).margin(1e-12));
    CHECK(s.cm == Approx(-0.001 * a_deg).margin(1e-12));
  }
  CHECK(linear.evaluate(10.0 * kDegree + 4.0 * std::numbers::pi).cl == Approx(0.1).margin(1e-12));
  CHECK(wrap_angle(3.0 * std::numbers::pi / 2.0) == Approx(-std::numbers::pi / 2.0).margin(1e-15));
}

// Intent: the uniform-cell interval lookup (issue 28) gives the same bits as the binary search it
// replaced: evaluate() equals bracket_index() + the spline (or chord) on every NREL 5MW airfoil,
// at every table point, one ulp either side of it, 20,000 angles over ±200° and ±π. Exact (==):
// the same interval and the same arithmetic.
TEST_CASE("polar lookup by cells equals the binary search bit for bit", "[unit][aero]") {
  const Params p = aero::testing::load_nrel5mw_deck();
  long checked = 0, differing = 0;
  for (const Polar& polar : p.airfoils) {
    const std::vector<double>& x = polar.alpha_rad();
    const std::vector<double> cl2 = natural_spline_second_derivatives(x, polar.cl());
    const std::vector<double> cd2 = natural_spline_second_derivatives(x, polar.cd());
    const std::vector<double> cm2 = natural_spline_second_derivatives(x, polar.cm());
    std::vector<double> angles = {-std::numbers::pi, std::numbers::pi, std::nextafter(std::numbers::pi, 0.0)};
    for (double a : x) angles.insert(angles.end(), {a, std::nextafter(a, -10.0), std::nextafter(a, 10.0)});
    for (int k = 0; k <= 20000; ++k) angles.push_back((-200.0 + 400.0 * k / 20000.0) * kDegree);
    for (double angle : angles) {
      const double a = wrap_angle(angle);
      const std::size_t i = bracket_index(std::span<const double>(x), a);
      AirfoilCoefficients expected;
      if (polar.interpolation() == PolarInterpolation::cubic_spline) {
        expected = {natural_spline_value(x, polar.cl(), cl2, i, a), natural_spline_value(x, polar.cd(), cd2, i, a),
                    natural_spline_value(x, polar.cm(), cm2, i, a)};
      } else {
        const double s = (a - x[i]) / (x[i + 1] - x[i]);
        expected = {lerp(polar.cl()[i], polar.cl()[i + 1], s), lerp(polar.cd()[i], polar.cd()[i + 1], s),
                    lerp(polar.cm()[i], polar.cm()[i + 1], s)};
      }
      const AirfoilCoefficients got = polar.evaluate(angle);
      if (got.cl != expected.cl || got.cd != expected.cd || got.cm != expected.cm) ++differing;
      ++checked;
    }
  }
  CHECK(differing == 0);  // exact: same interval, same arithmetic
  CHECK(checked > 8 * 20000);  // exact count: every airfoil and every angle was visited
}

// Intent: wrap_angle's shortcut for angles already in [−π, π) gives fmod's bits.
TEST_CASE("wrap_angle equals the fmod form bit for bit", "[unit][aero]") {
  const auto by_fmod = [](double angle) {
    double a = std::fmod(angle + std::numbers::pi, 2.0 * std::numbers::pi);
    if (a < 0.0) a += 2.0 * std::numbers::pi;
    return a - std::numbers::pi;
  };
  int differing = 0;
  for (int k = -40000; k <= 40000; ++k) {
    const double angle = 1e-4 * k + 1e-9 * (k % 7);
    if (wrap_angle(angle) != by_fmod(angle)) ++differing;
  }
  for (double angle : {-std::numbers::pi, std::nextafter(-std::numbers::pi, 0.0), std::nextafter(-std::numbers::pi, -4.0),
                       std::numbers::pi, std::nextafter(std::numbers::pi, 0.0), 0.0, -0.0, 1e-300})
    if (wrap_angle(angle) != by_fmod(angle)) ++differing;
  CHECK(differing == 0);  // exact: fmod of a value in [0, 2π) is that value
}

// Intent: tables that could break the solver or the lookup are refused before the run.
TEST_CASE("polar validation rejects bad tables", "[unit][aero]") {
  const std::vector<double> alpha = {-180.0, 0.0, 180.0}, ok = {0.0, 0.1, 0.0};
  CHECK_THROWS_AS(Polar("neg-cd", alpha, ok, {0.1, -0.01, 0.1}, ok, PolarInterpolation::linear), InputError);
  CHECK_THROWS_AS(Polar("short", {-180.0, 0.0, 170.0}, ok, ok, ok, PolarInterpolation::linear), InputError);
  CHECK_THROWS_AS(Polar("order", {-180.0, 180.0, 0.0}, ok, ok, ok, PolarInterpolation::linear), InputError);
  CHECK_THROWS_AS(Polar("sizes", alpha, {0.0}, ok, ok, PolarInterpolation::linear), InputError);
  CHECK_NOTHROW(Polar("fine", alpha, ok, {0.5, 0.5, 0.5}, ok, PolarInterpolation::cubic_spline));
}

// Intent: the deck is read completely (AeroDyn blade file: 19 nodes; 8 airfoil files).
TEST_CASE("NREL 5MW aero deck is complete", "[unit][aero]") {
  const Params p = aero::testing::load_nrel5mw_deck();
  REQUIRE(p.airfoils.size() == 8);
  REQUIRE(p.blade.size() == 19);
  CHECK(p.airfoils[p.blade.front().airfoil].name() == "Cylinder1");
  CHECK(p.airfoils[p.blade.back().airfoil].name() == "NACA64_A17");
  CHECK(p.blade.back().span_m == Approx(61.4999).margin(1e-12));
  CHECK(p.blade.front().twist_rad == Approx(13.308 * kDegree).margin(1e-15));
  CHECK(p.tower.size() == 11);
  Params bad = p;
  bad.blade[3].chord_m = -1.0;
  bad.number_of_blades = 0;
  CHECK_THROWS_AS(validate(bad), InputError);
}
