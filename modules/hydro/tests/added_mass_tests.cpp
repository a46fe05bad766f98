// The structure-acceleration part of Morison as a 6×6 added-mass matrix about the reference point.
#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>

#include "fowtsim/core/rotation.hpp"
#include "test_members.hpp"

using namespace fowtsim;
using namespace fowtsim::hydro;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kRho = 1025.0;
}  // namespace

TEST_CASE("vertical cylinder added mass matches the hand calculation", "[verification][hydro]") {
  // Intent: A11 = A22 = ρ C_a A L, A15 = −A24 = ρ C_a A ∫z dz = −ρ C_a A L²/2,
  // A44 = A55 = ρ C_a A ∫z² dz = ρ C_a A L³/3 (submerged length L = draft, reference at SWL),
  // A33 = A66 = 0 without axial added mass.
  const double D = 9.4, L = 120.0, ca = 0.97;
  const Params p = test::vertical_cylinder(D, L, 10.0, 0.6, ca, 400);
  const Mat6 a = Hydro::outputs(p, make_input(p), {}).added_mass;
  const double m = kRho * ca * kPi * D * D / 4.0;
  CHECK(a(0, 0) == Approx(m * L).epsilon(1e-13));  // constant integrand: rounding
  CHECK(a(1, 1) == Approx(m * L).epsilon(1e-13));
  CHECK(a(0, 4) == Approx(-m * L * L / 2).epsilon(1e-13));  // linear integrand: midpoint exact
  CHECK(a(1, 3) == Approx(m * L * L / 2).epsilon(1e-13));
  // Midpoint rule on z²: relative error 1/(4 N²) = 1.6e-6 at N = 400 (exact for the rule).
  CHECK(a(4, 4) == Approx(m * L * L * L / 3 * (1 - 1.0 / (4.0 * 400 * 400))).epsilon(1e-12));
  CHECK(a(3, 3) == Approx(a(4, 4)).epsilon(1e-13));
  CHECK(std::abs(a(2, 2)) < 1e-9 * m);
  CHECK(std::abs(a(5, 5)) < 1e-9 * m);
  CHECK((a - a.transpose()).norm() < 1e-12 * a.norm());
}

TEST_CASE("added mass transforms as a rigid-body 6x6 under rotation and with axial end terms", "[verification][hydro]") {
  // Intent: (1) for a rotated platform the matrix equals Φ A_0 Φᵀ with Φ = diag(T, T) (frame
  // covariance); (2) axial added mass of the bottom plate ρ C_a,ax (2/3)π R³ appears in A33 and,
  // at lever arm, nowhere else for a vertical member; (3) symmetric positive semi-definite.
  Params p = test::vertical_cylinder(6.0, 50.0, 8.0, 0.0, 1.0, 50);
  p.members[0].axial_ca_a = 0.64;
  const Mat6 a0 = Hydro::outputs(p, make_input(p), {}).added_mass;
  CHECK(a0(2, 2) == Approx(kRho * 0.64 * 2.0 / 3.0 * kPi * 27.0).epsilon(1e-13));
  // Fully submerged so the rotation does not change the wetted part: lower the member first.
  p.members[0].end_b_body_m.z() = -5.0;
  Hydro::Input in = make_input(p);
  in.platform.position_m = Vec3(3.0, -1.0, -20.0);
  const Mat6 upright = Hydro::outputs(p, in, {}).added_mass;
  const Mat3 T = euler123_to_matrix(Vec3(0.4, -0.7, 1.2));
  in.platform.orientation = T;
  const Mat6 rotated = Hydro::outputs(p, in, {}).added_mass;
  // Rotation about the reference point: the body-frame matrix is the same, so A = Φ A_b Φᵀ.
  Mat6 phi = Mat6::Zero();
  phi.topLeftCorner<3, 3>() = T;
  phi.bottomRightCorner<3, 3>() = T;
  CHECK((rotated - phi * upright * phi.transpose()).norm() < 1e-11 * upright.norm());
  const Eigen::SelfAdjointEigenSolver<Mat6> eig(rotated);
  CHECK(eig.eigenvalues().minCoeff() > -1e-9 * eig.eigenvalues().maxCoeff());
}

// Intent: HydroDyn's HydroF·i/HydroM·i (and B1Rdt·) hold the added-mass reaction −A [a; α]; ours
// keep A on the solver's left-hand side, so the channels add it back from the platform's
// acceleration: exactly total − A a, and the radiation part only A(∞).
TEST_CASE("the total hydro channels include the added-mass reaction of the platform's acceleration", "[unit][hydro]") {
  const fowtsim::hydro::Params params;  // no potential flow: 24 channels (total, hydrostatics, Morison, added linear)
  fowtsim::hydro::Hydro::Output out;
  out.total << 1.0, 2.0, 3.0, 4.0, 5.0, 6.0;
  out.added_mass = fowtsim::Mat6::Identity() * 1000.0;
  out.added_mass(0, 4) = out.added_mass(4, 0) = 50.0;  // surge–pitch coupling
  fowtsim::Vec6 acceleration;
  acceleration << 0.1, 0.0, -0.2, 0.0, 0.01, 0.0;
  std::vector<double> values(fowtsim::hydro::Hydro::channels(params).size());
  fowtsim::hydro::channel_values(params, out, acceleration, values);
  const fowtsim::Vec6 expected = out.total - out.added_mass * acceleration;
  for (int i = 0; i < 6; ++i) CHECK(values[static_cast<std::size_t>(i)] == expected[i]);
  CHECK(values[0] == 1.0 - (1000.0 * 0.1 + 50.0 * 0.01));
}
