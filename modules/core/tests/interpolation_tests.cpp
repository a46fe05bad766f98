#include <array>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/interpolation.hpp"

using namespace fowtsim;

TEST_CASE("linear interpolation is exact on linear data and holds end values", "[unit][interpolation]") {
  const std::vector<double> x{0.0, 1.0, 2.5, 4.0};
  std::vector<double> y;
  for (double xi : x) y.push_back(3.0 * xi - 1.0);
  for (double xq : {0.0, 0.3, 1.0, 2.0, 3.99, 4.0}) CHECK(interpolate_linear(x, y, xq) == Approx(3.0 * xq - 1.0).margin(1e-14));
  CHECK(interpolate_linear(x, y, -5.0) == y.front());
  CHECK(interpolate_linear(x, y, 9.0) == y.back());
}

TEST_CASE("bracket index finds the interval and clamps", "[unit][interpolation]") {
  const std::array<double, 4> x{0.0, 1.0, 2.0, 3.0};
  CHECK(bracket_index(x, -1.0) == 0);
  CHECK(bracket_index(x, 0.0) == 0);
  CHECK(bracket_index(x, 1.5) == 1);
  CHECK(bracket_index(x, 3.0) == 2);
  CHECK(bracket_index(x, 7.0) == 2);
}

TEST_CASE("bad tables are rejected with the table named", "[unit][interpolation]") {
  const std::vector<double> x{0.0, 1.0, 1.0}, y{1.0, 2.0};
  CHECK_THROWS_AS(interpolate_linear(x, y, 0.5), InputError);
  CHECK_THROWS_WITH(require_strictly_increasing(x, "airfoil alpha"), Catch::Contains("airfoil alpha"));
  CHECK(lerp(2.0, 4.0, 0.25) == 2.5);
}
