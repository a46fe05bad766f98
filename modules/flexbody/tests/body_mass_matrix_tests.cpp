// The flexible-body mass matrix of eq. 2 assembled from the shape integrals (eqs. 37–38), the
// rigid-body matrix of eq. 5, and the thin-beam terms of eqs. 28–29 and 31.
#include "fowtsim/flexbody/body_mass_matrix.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fowtsim::flexbody;

namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

// Eq. 2 straight from its definition, point by point at the deflected positions s = s₀ + Φ g.
Eigen::MatrixXd mass_matrix_by_definition(const std::vector<MassPoint>& pts, const Eigen::VectorXd& g) {
  const Eigen::Index nf = g.size();
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(6 + nf, 6 + nf);
  for (const MassPoint& p : pts) {
    const Eigen::Vector3d s = p.s0 + p.phi * g;
    Eigen::MatrixXd N(3, 6 + nf);  // v_P = [I, −s̃, Φ] v'
    N << Eigen::Matrix3d::Identity(), -skew(s), p.phi;
    M += p.dm * N.transpose() * N;
  }
  return M;
}

}  // namespace

TEST_CASE("eq. 38 from shape integrals equals eq. 2 by definition, 3-D curved body", "[unit]") {
  // A curved body (mean line in y and z) with three shapes mixing x, y and z components, at a
  // deflection of order one: every block of eq. 38 (skew(σ + Ψg), u_kl, Σ, Υ) is exercised.
  std::vector<MassPoint> pts;
  for (int k = 0; k < 40; ++k) {
    const double x = 0.25 * (k + 0.5);
    Eigen::Matrix<double, 3, Eigen::Dynamic> phi(3, 3);
    phi << 0.01 * x, 0.0, -0.02 * x * x,
           0.1 * x * x, -0.3 * x, 0.05 * std::sin(x),
           0.2 * x, 0.04 * x * x, std::cos(0.3 * x) - 1.0;
    pts.push_back({2.0 + 0.1 * k, Eigen::Vector3d(x, 0.05 * x * x, -0.1 * x), phi});
  }
  const Eigen::Vector3d g(0.7, -1.3, 0.4);
  const Eigen::MatrixXd A = body_mass_matrix(shape_integrals(pts), g);
  const Eigen::MatrixXd B = mass_matrix_by_definition(pts, g);
  // Same sums in a different order: rounding only (measured 1e-15 of the norm).
  CHECK((A - B).norm() < 1e-13 * B.norm());
  CHECK((A - A.transpose()).norm() == 0.0);
}

TEST_CASE("eq. 5 rigid body equals eq. 2 for point masses without shapes", "[unit]") {
  std::vector<MassPoint> pts;
  const Eigen::Vector3d r[] = {{1.0, 2.0, -0.5}, {-0.3, 0.4, 2.0}, {0.0, -1.5, 0.7}};
  const double dm[] = {3.0, 5.0, 2.0};
  double M = 0.0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  for (int k = 0; k < 3; ++k) {
    pts.push_back({dm[k], r[k], Eigen::Matrix<double, 3, Eigen::Dynamic>(3, 0)});
    M += dm[k];
    first += dm[k] * r[k];
    J -= dm[k] * skew(r[k]) * skew(r[k]);  // J' = −∫ s̃ s̃ dm (Sec. 2.2)
  }
  const Eigen::MatrixXd A = body_mass_matrix(shape_integrals(pts), Eigen::VectorXd(0));
  const Eigen::MatrixXd B = rigid_body_mass_matrix(M, first / M, J);
  CHECK((A - B).norm() < 1e-14 * B.norm());  // rounding
}

TEST_CASE("uniform beam u = x̃², closed forms of eq. 2 and of eqs. 28–29, 31", "[unit]") {
  // u = x̃² along z, L 10 m, m 3 kg/m: ∫m u = mL/3, ∫m x u = mL²/4, ∫m u² = mL/5, ∫m x² = mL³/3;
  // ν = 2x/L², T = m(L − x) + M_k: ∫ν T = mL/3 + M_k, ∫ν² T = m/3 + 4M_k/(3L).
  const double L = 10.0, m = 3.0, Mk = 7.0, jG = 0.4, g = 0.8;
  const ShapeFunction shape("x2", [L](double x) { return ShapeValue{x * x / (L * L), 2 * x / (L * L), 2 / (L * L)}; });
  const SampledBody body = sample(quadrature_points(uniform_beam(L, m, 1.0)), {shape});
  Eigen::MatrixXd M = body_mass_matrix(shape_integrals(straight_beam_mass_points(body, Eigen::Vector3d::UnitZ())),
                                       Eigen::VectorXd::Constant(1, g));
  const double tol = 1e-12;  // Gauss rule exact for these polynomials: rounding only
  CHECK(M(0, 0) == Approx(m * L).epsilon(tol));
  CHECK(M(0, 4) == Approx(g * m * L / 3).epsilon(tol));         // −skew(∫ s dm): +∫ s_z
  CHECK(M(2, 4) == Approx(-m * L * L / 2).epsilon(tol));        // −∫ s_x
  CHECK(M(3, 3) == Approx(g * g * m * L / 5).epsilon(tol));     // u_yy + u_zz
  CHECK(M(4, 4) == Approx(m * L * L * L / 3 + g * g * m * L / 5).epsilon(tol));
  CHECK(M(3, 5) == Approx(-g * m * L * L / 4).epsilon(tol));    // −u_xz
  CHECK(M(4, 6) == Approx(-m * L * L / 4).epsilon(tol));        // Σ_zx − Σ_xz
  CHECK(M(2, 6) == Approx(m * L / 3).epsilon(tol));
  CHECK(M(6, 6) == Approx(m * L / 5).epsilon(tol));
  CHECK(M(0, 6) == 0.0);  // eq. 2: no axial shape component

  add_section_inertia(M, jG * L);  // eq. 31, no torsion shapes
  CHECK(M(3, 3) == Approx(g * g * m * L / 5 + jG * L).epsilon(tol));

  // Eqs. 28–29 with the body's outboard mass and a tip mass M_k carried by T on [0, L].
  const AxialForce T = [L, m, Mk](double x) { return m * (L - x) + Mk; };
  apply_axial_inertia_correction(M, body, Eigen::VectorXd::Constant(1, g), T);
  CHECK(M(0, 4) == Approx(g * (m * L / 3 + Mk)).epsilon(tol));  // = ∫ s_z dm of beam + tip mass
  CHECK(M(4, 0) == M(0, 4));
  CHECK(M(0, 6) == Approx(-g * (m / 3 + 4 * Mk / (3 * L))).epsilon(tol));
  CHECK(M(6, 0) == M(0, 6));
}
