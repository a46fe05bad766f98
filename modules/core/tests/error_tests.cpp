#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/health.hpp"

using namespace fowtsim;

TEST_CASE("error message carries module, time, variable and hint", "[unit][error]") {
  const Error e({"beam", 312.45, "theta[17]", "reduce dt"}, "NaN in blade 2");
  const std::string what = e.what();
  CHECK_THAT(what, Catch::Contains("beam") && Catch::Contains("312.45") && Catch::Contains("theta[17]") &&
                       Catch::Contains("reduce dt") && Catch::Contains("NaN in blade 2"));
  REQUIRE(e.context().time_s);
  CHECK(*e.context().time_s == 312.45);
}

TEST_CASE("health checks catch NaN, Inf and divergence and pass finite values", "[unit][error]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_NOTHROW(check_finite("toy", "x", 1.0, 0.0));
  CHECK_THROWS_AS(check_finite("toy", "x", nan, 1.5), NumericalError);
  CHECK_THROWS_AS(check_finite("toy", "x", INFINITY, 1.5), NumericalError);
  Eigen::VectorXd v(3);
  v << 1.0, nan, 2.0;
  CHECK_THROWS_WITH(check_finite("toy", "state", v, 2.0), Catch::Contains("state[1]") && Catch::Contains("t = 2"));
  CHECK_THROWS_WITH(check_bounded("toy", "q", 1e9, 1e6, 3.0), Catch::Contains("divergence") && Catch::Contains("q"));
  CHECK_NOTHROW(check_bounded("toy", "q", -1e5, 1e6, 3.0));
}
