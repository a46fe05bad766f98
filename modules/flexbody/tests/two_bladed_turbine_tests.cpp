// Seed Sec. 6: the 4-DOF two-bladed turbine — body mass matrices at unit deflection (eq. 2 with the
// eq. 29 correction), M_q and K_q of eq. 36 at q = [1 1 1 1], and the stiffness coefficients printed
// in the text. The seed prints two significant digits (three for eq. 36): each value is asserted to
// half a unit of its last printed digit (what the rounding allows, no more), relative to the printed
// value. Printed zeros are zero by the planar symmetry of the model: asserted below 1e-12 of the
// matrix's scale (rounding). Values the seed prints that cannot be reproduced are asserted at what
// the physics gives and the reason is given beside them (README, "Seed Sec. 6").
#include "fowtsim/flexbody/two_bladed_turbine.hpp"
#include "fowtsim/flexbody/verification.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fowtsim::flexbody;

namespace {

// |value − printed| <= half a unit of the printed value's last digit (`digits` significant digits).
bool matches_print(double value, double printed, int digits) {
  return verification::printed_digit_error(value, printed, digits) <= 1.0;
}

const Eigen::Vector4d kUnit(1.0, 1.0, 1.0, 1.0);

}  // namespace

TEST_CASE("Sec. 6 tower and blade mass matrices at unit deflection match the seed's print",
          "[verification]") {
  const TurbineMatrices r = two_bladed_turbine_matrices(TwoBladedTurbine{}, kUnit);
  const Eigen::MatrixXd& Mt = r.tower_mass;
  // Seed's M'^t, upper triangle (1-based (i, j) in the comments), two significant digits.
  struct Entry { int i, j; double printed; };
  const Entry tower[] = {{1, 1, 9.0e5}, {1, 5, 3.4e5},  {2, 2, 9.0e5},  {2, 4, -3.4e5}, {2, 6, 4.5e7},
                         {3, 3, 9.0e5}, {3, 5, -4.5e7}, {3, 7, 3.4e5},  {4, 4, 2.2e5},  {4, 6, -2.5e7},
                         {5, 5, 3.0e9}, {5, 7, -2.5e7}, {6, 6, 3.0e9}};
  for (const Entry& e : tower) {
    INFO("M'^t(" << e.i << "," << e.j << ") = " << Mt(e.i - 1, e.j - 1));
    CHECK(matches_print(Mt(e.i - 1, e.j - 1), e.printed, 2));
    CHECK(Mt(e.j - 1, e.i - 1) == Mt(e.i - 1, e.j - 1));
  }
  // Printed zeros of M'^t, including M_17: eq. 29 would make it −∫ν² T dx = −3.4e3 (measured); the
  // print has 0, i.e. the tower matrix was built without eqs. 28–29 (welib's test of this example
  // builds its tower with bAxialCorr=False) — TwoBladedTurbine::tower_axial_correction = false.
  const int tower_zeros[][2] = {{1, 2}, {1, 3}, {1, 4}, {1, 6}, {1, 7}, {2, 3}, {2, 5}, {2, 7},
                                {3, 4}, {3, 6}, {4, 5}, {4, 7}, {5, 6}, {6, 7}};
  for (const auto& z : tower_zeros) CHECK(std::abs(Mt(z[0] - 1, z[1] - 1)) < 1e-12 * 3e9);
  CHECK(Mt(6, 6) == Approx(Mt(3, 3)).epsilon(1e-12));  // (7,7) not printed: ∫ m u² as (4,4)

  const Eigen::MatrixXd& Mb = r.blade_mass[0];
  const Entry blade[] = {{1, 1, 3.0e4}, {1, 5, 1.2e4},  {2, 2, 3.0e4},  {2, 4, -1.2e4}, {2, 6, 9.0e5},
                         {3, 3, 3.0e4}, {3, 5, -9.0e5}, {3, 7, 1.2e4},  {4, 4, 6.0e6},  {5, 5, 3.6e7},
                         {5, 7, -5.1e5}, {6, 6, 3.6e7}};
  for (const Entry& e : blade) {
    INFO("M'^b(" << e.i << "," << e.j << ") = " << Mb(e.i - 1, e.j - 1));
    CHECK(matches_print(Mb(e.i - 1, e.j - 1), e.printed, 2));
  }
  // Not reproduced, seed misprints (README):
  // - M'^b_17 is printed −2.0e4. Eq. 29 gives −∫ν² T dx with T = ∫_x^L m: −196.3 (measured; welib's
  //   hard-coded blade matrix for this example has −1.9634e2). Asserted at the print's digits with the
  //   exponent 2: −2.0e2.
  CHECK(matches_print(Mb(0, 6), -2.0e2, 2));
  // - M'^b_46 is printed −9.0e5; it is −u_13 = −∫ m x u q = M'^b_57 = −5.1e5 (printed in row 5; welib
  //   −5.1196e5). The print repeats the 9.0e5 of (2,6)/(3,5).
  CHECK(Mb(3, 5) == Approx(Mb(4, 6)).epsilon(1e-12));
  CHECK(matches_print(Mb(3, 5), -5.1e5, 2));
  // The two blades are identical at equal deflection (their frames differ, not their matrices).
  CHECK((r.blade_mass[1] - Mb).norm() < 1e-12 * Mb.norm());
}

TEST_CASE("Sec. 6 stiffness coefficients", "[verification]") {
  const TurbineMatrices r = two_bladed_turbine_matrices(TwoBladedTurbine{}, kUnit);
  CHECK(matches_print(r.tower_stiffness, 6.0e6, 2));    // K^tt_77, measured 6.0134e6
  CHECK(matches_print(r.tower_geometric, -1.0e5, 2));   // K^tt_g,77, measured −9.8817e4
  CHECK(matches_print(r.blade_stiffness, 2.9e5, 2));    // K^tb_77, measured 2.8617e5
  // K^tb_g,77 is printed −1.9e4. The blade's only axial load here is its self-weight (M_t = 0);
  // pointing up, eq. 26 gives −g ∫ν² ∫_x^L m = −1.926e3 (measured), a value independent of the
  // blade's length and EI for a uniform blade (ν ∝ 1/L) — so neither the 75 m of the text nor any
  // other length gives −1.9e4. The print is 10× ours with the same two digits: asserted at −1.9e3.
  CHECK(matches_print(r.blade_geometric, -1.9e3, 2));
}

TEST_CASE("Sec. 6 eq. 36: M_q and K_q at q = [1 1 1 1]", "[verification]") {
  const TurbineMatrices r = two_bladed_turbine_matrices(TwoBladedTurbine{}, kUnit);
  const Eigen::Matrix4d& M = r.Mq;
  const Eigen::Matrix4d& K = r.Kq;
  CHECK(matches_print(M(0, 0), 7.86e5, 3));  // measured 7.8628e5
  CHECK(matches_print(M(1, 1), 7.23e7, 3));  // 7.2300e7: J_s,zz + 2 ∫ m x²
  CHECK(matches_print(M(2, 2), 7.50e3, 3));  // ∫ m u² = mL/4 = 7500
  CHECK(matches_print(M(3, 3), 7.50e3, 3));
  CHECK(matches_print(M(0, 3), 1.58e4, 3));  // measured 1.5782e4
  // M_q13 is printed 7.71e3; ours is 7.7048e3 (converged quadrature) and 7.70497e3 with the author's
  // discretisation (trapezoid on 101/61 stations, which reproduces his blade matrix, test below). The
  // half-unit criterion (±5) fails: |Δ| = 5.2; a double rounding 7.70497 → 7.705 → 7.71
  // would print it. welib's own test of this example asserts 7.71e3 at rtol 1e-3: that is the
  // published tolerance we can check against (|Δ|/7.71e3 = 6.7e-4).
  CHECK_FALSE(matches_print(M(0, 2), 7.71e3, 3));
  CHECK(M(0, 2) == Approx(7.71e3).epsilon(1e-3));
  CHECK(matches_print(M(0, 2), 7.70e3, 3));
  const int zeros[][2] = {{0, 1}, {1, 2}, {1, 3}, {2, 3}};
  for (const auto& z : zeros) {
    CHECK(std::abs(M(z[0], z[1])) < 1e-12 * M(1, 1));
    CHECK(std::abs(M(z[1], z[0])) < 1e-12 * M(1, 1));
  }
  CHECK(matches_print(K(0, 0), 6.01e6, 3));  // measured 6.0134e6
  CHECK(matches_print(K(2, 2), 2.86e5, 3));  // measured 2.8617e5
  // K_q44 is printed 2.86e6: the two blades are identical, K_q44 = K_q33 = 2.86e5 (welib's test
  // asserts KK[2,2] only).
  CHECK(K(3, 3) == Approx(K(2, 2)).epsilon(1e-12));
  CHECK(K(1, 1) == 0.0);  // the azimuth stores no strain energy
  CHECK((K - Eigen::Matrix4d(K.diagonal().asDiagonal())).norm() == 0.0);
}

TEST_CASE("Sec. 6 with the author's discretisation reproduces welib's numbers", "[verification]") {
  // welib yams tests_numeric_recursive/test_TNSB_article.py: tower by trapezoid on 101 stations,
  // its hard-coded blade matrix (from the author's Matlab code) consistent with 61 stations.
  TwoBladedTurbine t;
  t.rule.kind = QuadratureRule::Kind::StationTrapezoid;
  const TurbineMatrices r = two_bladed_turbine_matrices(t, kUnit);
  // Twr.KKg[6,6] = −98815.131096 asserted there at rtol 1e-10 (same top mass 560 t, g = 9.81);
  // measured agreement 1e-9 relative (its shape normalisation and ours differ in rounding only).
  CHECK(r.tower_geometric == Approx(-98815.131096).epsilon(1e-8));
  // Blade matrix entries, five printed digits, half a unit of the last.
  const Eigen::MatrixXd& Mb = r.blade_mass[0];
  CHECK(matches_print(Mb(0, 4), 1.1741e4, 5));   // eq. 28: ∫ ν T dx (trapezoid)
  CHECK(matches_print(Mb(0, 6), -1.9634e2, 5));  // eq. 29
  CHECK(matches_print(Mb(2, 6), 1.1746e4, 5));   // ∫ m u
  CHECK(matches_print(Mb(3, 3), 6.0075e6, 5));   // j_G L + ∫ m u²
  CHECK(matches_print(Mb(6, 6), 7.5019e3, 5));   // ∫ m u²
  // Not matched, by design: welib's 'Flex' rule integrates ∫ m x f with weights exact for f linear
  // between stations; the trapezoid differs by m h²/6 [f(L) − f(0)]: +5000 on ∫ m x² (our 3.60125e7
  // vs its 3.6008e7) and −m h²/6 = −83.3 on ∫ m x u (−5.1204e5 vs −5.1196e5).
  // With h = 1 m: our ∫ m x² − 5000 and ∫ m x u + 83.3 then match its print to half a unit.
  const double h = 60.0 / 60.0, flex = 500.0 * h * h / 6.0;
  CHECK(matches_print(Mb(4, 4) - flex * 60.0, 3.6008e7, 5));
  CHECK(matches_print(Mb(4, 6) + flex, -5.1196e5, 5));
}
