#include "fowtsim/core/error.hpp"
#include "fowtsim/flexbody/integrals.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fowtsim::flexbody;

TEST_CASE("Gauss–Legendre panels integrate degree 2n−1 exactly and carry linear properties", "[unit]") {
  const BeamStations s{{0.0, 3.0, 10.0}, {2.0, 4.0, 1.0}, {1.0, 1.0, 1.0}};
  for (int n : {1, 3, 8}) {
    const auto pts = quadrature_points(s, {QuadratureRule::Kind::GaussLegendre, 2, n});
    const int k = 2 * n - 1;
    double sum = 0.0, mass = 0.0;
    for (const auto& p : pts) {
      sum += p.w * std::pow(p.x, k);
      mass += p.w * p.m;
    }
    CHECK(sum == Approx(std::pow(10.0, k + 1) / (k + 1)).epsilon(1e-13));  // rounding only
    CHECK(mass == Approx(0.5 * 3 * (2 + 4) + 0.5 * 7 * (4 + 1)).epsilon(1e-14));  // m linear: exact
  }
}

TEST_CASE("Default quadrature error on the eq. 32 modes, measured by refinement", "[unit]") {
  // The default rule (8 panels × 8 points per interval) against 4× the panels, for M_q and K_q of
  // four cantilever modes (β up to 11) on one interval (the worst case: a uniform beam).
  const auto body = uniform_beam(60.0, 500.0, 2e10);
  std::vector<ShapeFunction> modes;
  for (int j = 1; j <= 4; ++j) modes.push_back(clamped_free_mode(j, 60.0));
  const auto coarse = sample(quadrature_points(body), modes);
  const auto fine = sample(quadrature_points(body, {QuadratureRule::Kind::GaussLegendre, 32, 8}), modes);
  const Eigen::MatrixXd dM = generalized_mass(coarse) - generalized_mass(fine);
  const Eigen::MatrixXd dK = generalized_stiffness(coarse) - generalized_stiffness(fine);
  CHECK(dM.cwiseAbs().maxCoeff() / generalized_mass(fine).cwiseAbs().maxCoeff() < 1e-13);
  CHECK(dK.cwiseAbs().maxCoeff() / generalized_stiffness(fine).cwiseAbs().maxCoeff() < 1e-13);
}

TEST_CASE("Quadrature refuses a station table that is not a body", "[unit]") {
  using fowtsim::InputError;
  CHECK_THROWS_AS(quadrature_points({{0.0}, {1.0}, {1.0}}), InputError);
  CHECK_THROWS_AS(quadrature_points({{1.0, 2.0}, {1.0, 1.0}, {1.0, 1.0}}), InputError);
  CHECK_THROWS_AS(quadrature_points({{0.0, 2.0, 2.0}, {1.0, 1.0, 1.0}, {1.0, 1.0, 1.0}}), InputError);
  CHECK_THROWS_AS(quadrature_points({{0.0, 2.0}, {1.0, 1.0}, {1.0, 0.0}}), InputError);
  CHECK_THROWS_AS(quadrature_points({{0.0, 2.0}, {1.0}, {1.0, 1.0}}), InputError);
  CHECK_THROWS_AS(quadrature_points(uniform_beam(1, 1, 1), {QuadratureRule::Kind::GaussLegendre, 0, 4}), InputError);
}
