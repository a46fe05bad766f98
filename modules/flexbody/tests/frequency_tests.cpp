// Rayleigh–Ritz eigenproblems assembled from the module's integrals, against analytic beam theory.
#include "fowtsim/flexbody/integrals.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

using namespace fowtsim::flexbody;
using std::numbers::pi;

namespace {

// Generalised symmetric eigenvalues of A v = λ B v (B positive definite), ascending.
Eigen::VectorXd eigenvalues(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  return Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(A, B, Eigen::EigenvaluesOnly).eigenvalues();
}

// u = x̃^j, j = 2..n+1: complete clamped polynomials (ElastoDyn's space for n = 5).
std::vector<ShapeFunction> monomials(int n, double L) {
  std::vector<ShapeFunction> out;
  for (int j = 2; j <= n + 1; ++j) {
    std::array<double, 5> c{};
    c[static_cast<std::size_t>(j - 2)] = 1.0;
    out.push_back(polynomial_shape(c, L));
  }
  return out;
}

const double L = 100.0, EI = 2e12, m = 9e3;

}  // namespace

TEST_CASE("RR frequencies of the clamped-free beam with polynomial shapes vs β_n L", "[verification]") {
  const auto body = sample(quadrature_points(uniform_beam(L, m, EI)), monomials(4, L));
  const Eigen::VectorXd w2 = eigenvalues(generalized_stiffness(body), generalized_mass(body));
  // RR bounds from above; errors measured with x̃²..x̃⁵: 1.54e-6, 5.6e-3, 2.67e-2 — the bounds are
  // those ×~3 (mode 3 is the highest a 4-term space resolves at all).
  const double bound[3] = {5e-6, 2e-2, 8e-2};
  for (int n = 1; n <= 3; ++n) {
    const double exact = std::pow(clamped_free_beta(n) / L, 2) * std::sqrt(EI / m);
    const double rr = std::sqrt(w2(n - 1));
    INFO("mode " << n << ": RR " << rr << " rad/s, exact " << exact << ", rel. error " << rr / exact - 1);
    CHECK(rr >= exact * (1 - 1e-12));  // Rayleigh–Ritz is an upper bound
    CHECK(rr / exact - 1 < bound[n - 1]);
  }
}

TEST_CASE("Eq. 32 modes with a top mass give the top-mass beam's frequencies", "[verification]") {
  // M_t = 0.5 M: RR on the first 4 top-mass modes with the tip mass added to M_q (u_j(L) = 1)
  // reproduces ω_j = (β_j/L)² sqrt(EI/m) of eq. 32's frequency equation — exact, as these modes are
  // the eigenfunctions; tolerance 1e-10 covers quadrature (1e-13) and eigen-solver rounding.
  const double mu = 0.5, Mt = mu * m * L;
  std::vector<ShapeFunction> modes;
  for (int j = 1; j <= 4; ++j) modes.push_back(clamped_free_mode(j, L, mu));
  const auto body = sample(quadrature_points(uniform_beam(L, m, EI)), modes);
  const Eigen::MatrixXd M = generalized_mass(body) + Mt * Eigen::MatrixXd::Ones(4, 4);
  const Eigen::VectorXd w2 = eigenvalues(generalized_stiffness(body), M);
  for (int j = 1; j <= 4; ++j)
    CHECK(std::sqrt(w2(j - 1)) == Approx(std::pow(clamped_free_beta(j, mu) / L, 2) * std::sqrt(EI / m)).epsilon(1e-10));
}

TEST_CASE("Geometric stiffness of eq. 26 buckles the column at Euler's and Greenhill's loads", "[verification]") {
  // K_q + λ K^T(unit load) is singular at the critical load λ: the smallest λ of K_q v = λ (−K^T) v.
  const auto stations = uniform_beam(L, m, EI);
  const auto body = sample(quadrature_points(stations), monomials(5, L));
  const Eigen::MatrixXd K = generalized_stiffness(body);
  // Top (dead) load: P_cr = π² EI / (4L²). RR upper bound; measured +8.6e-9 with x̃²..x̃⁶ (bound ~3×).
  const double p = eigenvalues(K, -geometric_stiffness(body, top_mass_axial_force(1.0, 1.0)))(0);
  CHECK(p / (pi * pi * EI / (4 * L * L)) - 1 < 3e-8);
  CHECK(p / (pi * pi * EI / (4 * L * L)) - 1 > -1e-12);
  // Self weight: critical total weight (mgL)_cr = 7.8373 EI/L² (Greenhill; Timoshenko & Gere,
  // Theory of elastic stability, §2.13). Unit g gives λ = g_cr; tolerance: the 5-digit constant.
  const double g_cr = eigenvalues(K, -geometric_stiffness(body, self_weight_axial_force(stations, 1.0)))(0);
  CHECK(g_cr * m * L / (EI / (L * L)) == Approx(7.8373).epsilon(5e-5));
}
