// Each toy subsystem alone against its closed-form solution, and the exact coupled solution
// against independent checks (energy conservation, closed-form 2-DOF frequencies).
#include <cmath>

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>

#include "fowtsim/core/module.hpp"
#include "fowtsim/toy/exact_solution.hpp"

using namespace fowtsim;
using namespace fowtsim::toy;

static_assert(Module<SlowOscillator>);
static_assert(Module<FastOscillator>);

namespace {

// Max error of the slow oscillator alone (no interface load) over [0, 10] s vs X0 cos(ω t).
double slow_alone_error(double dt) {
  SlowOscillator::Params p;
  auto s = SlowOscillator::make_state(p);
  const double w = std::sqrt(p.stiffness_N_m / p.mass_kg);
  double err = 0.0;
  const int n = static_cast<int>(std::lround(10.0 / dt));
  for (int i = 0; i < n; ++i) {
    SlowOscillator::advance(p, {}, i * dt, dt, s);
    err = std::max(err, std::abs(s.position_m - p.initial_position_m * std::cos(w * (i + 1) * dt)));
  }
  return err;
}

// Max error of the fast oscillator alone under a constant frame acceleration a over [0, 1] s
// vs the closed form q = −(m a / k)(1 − cos ω t).
double fast_alone_error(double dt) {
  FastOscillator::Params p;
  p.initial_position_m = 0.0;
  auto s = FastOscillator::make_state(p);
  FastOscillator::Input u;
  u.frame_begin.acceleration_m_s2.x() = 2.0;
  u.frame_end.acceleration_m_s2.x() = 2.0;
  const double w = std::sqrt(p.stiffness_N_m / p.mass_kg), qs = -p.mass_kg * 2.0 / p.stiffness_N_m;
  double err = 0.0;
  const int n = static_cast<int>(std::lround(1.0 / dt));
  for (int i = 0; i < n; ++i) {
    FastOscillator::advance(p, u, i * dt, dt, s);
    err = std::max(err, std::abs(s.position_m - qs * (1.0 - std::cos(w * (i + 1) * dt))));
  }
  return err;
}

}  // namespace

TEST_CASE("slow oscillator alone converges at 4th order to the cosine solution", "[verification][toy]") {
  const double order = std::log2(slow_alone_error(0.1) / slow_alone_error(0.05));
  CHECK(order == Approx(4.0).margin(0.1));  // classical RK4; measured 4.007
}

TEST_CASE("fast oscillator alone under constant frame acceleration converges at 4th order", "[verification][toy]") {
  const double order = std::log2(fast_alone_error(0.004) / fast_alone_error(0.002));
  CHECK(order == Approx(4.0).margin(0.1));  // classical RK4; measured 3.975
}

TEST_CASE("exact coupled solution conserves energy when undamped", "[verification][toy]") {
  SlowOscillator::Params s;
  FastOscillator::Params f;
  const ExactSolution exact(s, f);
  const double e0 = mechanical_energy(s, f, exact.state_at(0.0));
  for (double t : {1.0, 7.3, 40.0}) {
    CHECK(mechanical_energy(s, f, exact.state_at(t)) == Approx(e0).epsilon(1e-10));  // expm rounding ~1e-13
  }
}

TEST_CASE("exact coupled frequencies match the closed-form 2-DOF roots", "[verification][toy]") {
  SlowOscillator::Params s;
  FastOscillator::Params f;
  // det(K − ω² M) = 0 with M = [[M+m, m], [m, m]], K = diag(K, k): a quadratic in ω².
  const double a = (s.mass_kg + f.mass_kg) * f.mass_kg - f.mass_kg * f.mass_kg;
  const double b = -(s.stiffness_N_m * f.mass_kg + f.stiffness_N_m * (s.mass_kg + f.mass_kg));
  const double c = s.stiffness_N_m * f.stiffness_N_m;
  const double disc = std::sqrt(b * b - 4 * a * c);
  const Eigen::Vector2d w = ExactSolution(s, f).natural_frequencies_rad_s();
  CHECK(w[0] == Approx(std::sqrt((-b - disc) / (2 * a))).epsilon(1e-12));
  CHECK(w[1] == Approx(std::sqrt((-b + disc) / (2 * a))).epsilon(1e-12));
  // The system's eigenvalues (undamped) are ±iω: same frequencies from A.
  Eigen::EigenSolver<Eigen::Matrix4d> eig(ExactSolution(s, f).system_matrix());
  double wmax = 0.0;
  for (int i = 0; i < 4; ++i) wmax = std::max(wmax, std::abs(eig.eigenvalues()[i].imag()));
  CHECK(wmax == Approx(w[1]).epsilon(1e-10));
}

TEST_CASE("toy modules report divergence with module, variable and time", "[unit][toy]") {
  FastOscillator::Params p;
  p.divergence_limit_m = 1e-3;
  auto s = FastOscillator::make_state(p);
  FastOscillator::Input u;
  u.frame_begin.acceleration_m_s2.x() = 1e3;
  u.frame_end.acceleration_m_s2.x() = 1e3;
  CHECK_THROWS_WITH(FastOscillator::advance(p, u, 2.0, 0.01, s),
                    Catch::Contains("toy.fast") && Catch::Contains("q (fast") && Catch::Contains("t = 2.01"));
}
