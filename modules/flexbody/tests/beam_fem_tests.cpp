// The Hermite beam FEM and its Guyan / Craig–Bampton reductions against beam theory.
#include "fowtsim/flexbody/beam_fem.hpp"
#include "fowtsim/flexbody/reduction.hpp"
#include "fowtsim/flexbody/shape_functions.hpp"
#include "fowtsim/flexbody/station_segment.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Eigenvalues>
#include <cmath>

using namespace fowtsim::flexbody;

namespace {

Eigen::VectorXd eigenvalues(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M) {
  return Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(K, M, Eigen::EigenvaluesOnly).eigenvalues();
}

const double L = 100.0, EI = 2e12, m = 9e3;  // the uniform beam of Sec. 5.1

}  // namespace

TEST_CASE("segment re-bases a station table and interpolates its ends", "[unit]") {
  const BeamStations s{{0.0, 10.0, 30.0}, {100.0, 80.0, 40.0}, {5.0, 3.0, 1.0}};
  const BeamStations g = segment(s, 5.0, 20.0);
  REQUIRE(g.x.size() == 3);
  // By hand: x = 5 is halfway on [0, 10] (m 90, EI 4); x = 20 halfway on [10, 30] (m 60, EI 2).
  CHECK(g.x == std::vector<double>{0.0, 5.0, 15.0});
  CHECK(g.m == std::vector<double>{90.0, 80.0, 60.0});
  CHECK(g.EI == std::vector<double>{4.0, 3.0, 2.0});
}

TEST_CASE("FEM with 50 Hermite elements: clamped-free frequencies vs β_n L", "[verification]") {
  const BeamFem fem = clamped_beam_fem(uniform_beam(L, m, EI), 50);
  REQUIRE(fem.M.rows() == 100);
  const Eigen::VectorXd w2 = eigenvalues(fem.K, fem.M);
  // Consistent-mass Hermite elements converge as (β h)^4 from above; measured errors
  // 2.8e-9, 5.4e-8, 4.2e-7, 1.6e-6 (the ~1e-6 expected at 50 elements) — bounds ~2× those.
  const double bound[4] = {6e-9, 1.1e-7, 9e-7, 3.3e-6};
  for (int n = 1; n <= 4; ++n) {
    const double exact = std::pow(clamped_free_beta(n) / L, 2) * std::sqrt(EI / m);
    const double err = std::sqrt(w2(n - 1)) / exact - 1;
    INFO("mode " << n << ": rel. error " << err);
    CHECK(err > -1e-13);  // conforming FEM is a Rayleigh–Ritz method: an upper bound
    CHECK(err < bound[n - 1]);
  }
}

TEST_CASE("Guyan reduction to the tip: the exact static stiffness of the cantilever", "[verification]") {
  // Hermite cubics hold the exact static solution of a uniform beam under end loads, so the
  // condensed tip stiffness is EI/L³ [12 −6L; −6L 4L²] for any mesh; 1e-9 is the rounding of
  // the 40-DOF solve (condition ~1e8).
  const BeamFem fem = clamped_beam_fem(uniform_beam(L, m, EI), 20);
  const ReducedBody gy = craig_bampton(fem.M, fem.K, 2, 0);
  Eigen::Matrix2d exact;
  exact << 12.0, -6.0 * L, -6.0 * L, 4.0 * L * L;
  exact *= EI / (L * L * L);
  CHECK((gy.K - exact).norm() / exact.norm() < 1e-9);
  CHECK(gy.M.rows() == 2);
}

TEST_CASE("Craig–Bampton with all fixed-interface modes is a change of basis", "[verification]") {
  // k = all slaves: T is square and invertible, so the reduced eigenvalues are the full model's.
  // 1e-9 relative: eigen-solver rounding on a 20-DOF pencil spanning 8 decades of ω².
  const BeamFem fem = clamped_beam_fem(uniform_beam(L, m, EI), 10);
  const ReducedBody cb = craig_bampton(fem.M, fem.K, 2, 18);
  const Eigen::VectorXd full = eigenvalues(fem.K, fem.M), red = eigenvalues(cb.K, cb.M);
  for (int i = 0; i < 20; ++i) CHECK(std::abs(red(i) / full(i) - 1) < 1e-9);
  // The fixed-interface block is diagonal with the clamped–clamped ω² (mass-normalised modes).
  CHECK(cb.M.topLeftCorner(18, 18).isIdentity(1e-9));
}

TEST_CASE("FEM integrates between the stations exactly", "[verification]") {
  // A linear taper given by 2 stations or by 3 (the middle one on the line, off the element
  // nodes) is the same beam: matrices equal to rounding (1e-12).
  const BeamStations two{{0.0, 100.0}, {9e3, 5e3}, {2e12, 1e12}};
  const BeamStations three{{0.0, 37.0, 100.0}, {9e3, 9e3 - 0.37 * 4e3, 5e3}, {2e12, 2e12 - 0.37e12, 1e12}};
  const BeamFem a = clamped_beam_fem(two, 7), b = clamped_beam_fem(three, 7);
  CHECK((a.M - b.M).norm() / a.M.norm() < 1e-12);
  CHECK((a.K - b.K).norm() / a.K.norm() < 1e-12);
}

TEST_CASE("FEM and reduction reject bad sizes", "[unit]") {
  const BeamStations beam = uniform_beam(L, m, EI);
  CHECK_THROWS(clamped_beam_fem(beam, 0));
  CHECK_THROWS(segment(beam, 50.0, 50.0));
  const BeamFem fem = clamped_beam_fem(beam, 3);
  CHECK_THROWS(craig_bampton(fem.M, fem.K, 6, 0));
  CHECK_THROWS(craig_bampton(fem.M, fem.K, 2, 5));
}
