// Static benchmarks of seed 000 §2.5.1–2.5.2 solved by the piecewise-linear static solver.
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/beam/beam_outputs.hpp"
#include "fowtsim/beam/benchmarks.hpp"
#include "fowtsim/beam/solvers.hpp"

using namespace fowtsim;
using namespace fowtsim::beam;



TEST_CASE("tip-moment roll-up closes the circle with second-order spatial convergence",
          "[verification][beam]") {
  const std::vector<int> segments{5, 10, 20, 50, 100, 200};
  std::vector<double> rmse;
  for (int n : segments) rmse.push_back(benchmarks::rollup_rmse(n));
  // Least-squares slope of log RMSE against log element size.
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const double x = std::log(1.0 / segments[i]), y = std::log(rmse[i]);
    sx += x; sy += y; sxx += x * x; sxy += x * y;
  }
  const double k = static_cast<double>(segments.size());
  const double order = (k * sxy - sx * sy) / (k * sxx - sx * sx);
  INFO("RMSE 5…200 elements: " << rmse[0] << " " << rmse[1] << " " << rmse[2] << " " << rmse[3]
                               << " " << rmse[4] << " " << rmse[5] << ", order " << order);
  CHECK(std::abs(order - 2.0) < 0.2);  // issue 3 / seed Fig. 2.5: second order ± 0.2
  CHECK(rmse.back() < 1e-4);           // the 200-element circle of diameter 1/π is closed
}

TEST_CASE("45-degree curved cantilever matches the seed's converged tip coordinates",
          "[verification][beam]") {
  // Seed Table 2.2 (MBBT, converged): F = 300 → (58.78, 40.20, 22.25), F = 600 → (47.15, 53.47,
  // 15.69) in the seed's axes, where the arc starts along x and bends towards z. Our arc starts
  // along z and bends towards x (BeamDyn's): compared in the seed's axes.
  for (const auto& [force, expected] : {std::pair{300.0, Vec3(58.78, 40.20, 22.25)},
                                       std::pair{600.0, Vec3(47.15, 53.47, 15.69)}}) {
    const Vec3 seed_axes = benchmarks::curved_beam_tip_seed_axes(128, force);
    INFO("F = " << force << ": tip (seed axes) " << seed_axes.transpose());
    // Issue 3: within 0.1 of the seed's converged values (the table prints 2 decimals).
    CHECK((seed_axes - expected).cwiseAbs().maxCoeff() < 0.1);
  }
}

TEST_CASE("heavy cantilever under gravity matches the inextensible elastica", "[verification][beam]") {
  // BeamDyn r-test bd_static_cantilever_beam, made inextensible and unshearable (EA, GA = 1e8)
  // so that the exact answer is the elastica EI θ'' = −q (L − s) cos θ, θ(0) = 0, θ'(L) = 0,
  // q = m g: L = 10 m, EI = 100 N·m², m = 1 kg/m, g = 9.806 m/s² across the beam.
  const double length = 10.0, ei = 100.0, q = 9.806;
  // Exact answer by shooting on θ'(0) with RK4 (20000 steps: error ~1e-12) and bisection.
  auto shoot = [&](double k0, Vec3& tip) {
    const int n = 20000;
    const double h = length / n;
    double th = 0.0, k = k0, x = 0.0, z = 0.0;
    auto f = [&](double s, double a, double b) { return std::pair{b, -q * (length - s) * std::cos(a) / ei}; };
    for (int i = 0; i < n; ++i) {
      const double s = i * h;
      const auto [a1, b1] = f(s, th, k);
      const auto [a2, b2] = f(s + h / 2, th + h / 2 * a1, k + h / 2 * b1);
      const auto [a3, b3] = f(s + h / 2, th + h / 2 * a2, k + h / 2 * b2);
      const auto [a4, b4] = f(s + h, th + h * a3, k + h * b3);
      const double th1 = th + h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
      x += h / 2 * (std::sin(th) + std::sin(th1));  // trapezoid: O(h²) ≈ 1e-7 m
      z += h / 2 * (std::cos(th) + std::cos(th1));
      k += h / 6 * (b1 + 2 * b2 + 2 * b3 + b4);
      th = th1;
    }
    tip = Vec3(x, 0.0, z);
    return k;  // θ'(L)
  };
  double lo = 0.0, hi = 5.0;
  Vec3 exact;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (shoot(mid, exact) > 0.0 ? hi : lo) = mid;
  }
  shoot(0.5 * (lo + hi), exact);

  BeamDefinition def{ReferenceLine::straight(Vec3::Zero(), Mat3::Identity(), length, [](double) { return 0.0; }), {}};
  Station st;
  st.stiffness = (Vec6() << 1e8, 1e8, 1e8, ei, ei, 200.0).finished().asDiagonal();
  st.mass = Vec6::Ones().asDiagonal();
  st.eta = 0.0;
  def.stations.push_back(st);
  st.eta = 1.0;
  def.stations.push_back(st);
  const BeamModel model = discretise(def, 128);
  BeamState state = make_state(model);
  BeamInput in;
  in.frame.gravity_m_s2 = Vec3(q, 0.0, 0.0);
  StaticOptions opt;
  opt.load_steps = 4;
  solve_static(model, in, state, opt);
  const Vec3 tip = beam_outputs(model, state).tip_position_m;
  INFO("tip " << tip.transpose() << " vs elastica " << exact.transpose());
  // 128 finite volumes, second order: measured 1e-4 m with 128 and 6e-4 m with 64 segments.
  CHECK((tip - exact).norm() < 5e-4);
}
