// The analytic catenary against independent answers: (1) the equilibrium ODE of the elastic line
// with seabed friction, integrated numerically from the fairlead down to the anchor with the
// solved fairlead tensions — it must land on the anchor and reproduce the profile; (2) the
// inextensible limit against the textbook catenary z = a cosh((x − x₀)/a) + c.
#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include "fowtsim/core/rk4.hpp"
#include "fowtsim/mooring/catenary.hpp"

using namespace fowtsim;
using namespace fowtsim::mooring;

namespace {

struct OdeResult {
  double touchdown_z_m;                 // z where V reaches 0 (must be the seabed, z = 0)
  Eigen::Vector2d anchor_m;             // (x, z) reached at s = 0 (must be the anchor, (0, 0))
  double anchor_h_N;                    // H reached at s = 0
  double max_profile_error_m;           // max |ODE point − catenary_point| over the integration grid
};

// Equilibrium of an element ds of unstretched length, tension (H, V) pointing towards the
// fairlead: dH/ds = f_friction, dV/ds = w while suspended; on the seabed V = 0 and dH/ds = C_B w
// while H > 0 (friction opposes the pull towards the fairlead, none once the line is slack).
// Stretched geometry: d(x, z)/ds = (H, V)/T (1 + T/EA). Integrated with RK4 from s = L (at the
// fairlead (X, Z), with the solved H, V) down to s = 0, step ≈ ds_m; grid points are put on the
// ODE's own switching points (V = 0, and H = 0 on the seabed) so RK4 never steps over a kink.
OdeResult integrate_down(const CatenaryLine& line, const CatenarySolution& sol, double ds_m) {
  const double l = line.unstretched_length_m, w = line.weight_per_length_N_m, ea = line.ea_N;
  const double cbw = line.seabed_friction * w;
  OdeResult r{0.0, {}, 0.0, 0.0};
  // y = (x, z, H, V); the right-hand side is d/ds along increasing s.
  const auto suspended = [&](double, const Eigen::Vector4d& y) {
    const double t = std::hypot(y[2], y[3]), stretch = 1.0 + t / ea;
    return Eigen::Vector4d(y[2] / t * stretch, y[3] / t * stretch, 0.0, w);
  };
  const auto grounded = [&](double, const Eigen::Vector4d& y) {
    const double h = std::max(y[2], 0.0);
    return Eigen::Vector4d(1.0 + h / ea, 0.0, h > 0.0 ? cbw : 0.0, 0.0);
  };
  const auto march = [&](auto rhs, Eigen::Vector4d y, double s_from, double s_to) {
    const int n = std::max(1, static_cast<int>(std::ceil((s_from - s_to) / ds_m)));
    const double h = (s_to - s_from) / n;  // negative: marching towards the anchor
    for (int k = 0; k < n; ++k) {
      y = rk4_step(y, s_from + k * h, h, rhs);
      const Eigen::Vector2d exact = catenary_point(line, sol, s_from + (k + 1) * h);
      r.max_profile_error_m = std::max(r.max_profile_error_m, (y.head<2>() - exact).cwiseAbs().maxCoeff());
    }
    return y;
  };
  Eigen::Vector4d y(sol.span_x_m, sol.span_z_m, sol.fairlead_h_N, sol.fairlead_v_N);
  const double s_touchdown = line.seabed_contact ? std::max(l - sol.fairlead_v_N / w, 0.0) : 0.0;
  y = march(suspended, y, l, s_touchdown);
  r.touchdown_z_m = y[1];
  if (s_touchdown > 0.0) {
    y[3] = 0.0;  // the seabed carries the weight from here on
    const double s_slack = cbw > 0.0 ? std::max(s_touchdown - y[2] / cbw, 0.0) : 0.0;
    y = march(grounded, y, s_touchdown, s_slack);
    if (s_slack > 0.0) y = march(grounded, y, s_slack, 0.0);
  }
  r.anchor_m = y.head<2>();
  r.anchor_h_N = std::max(y[2], 0.0);
  return r;
}

// The ODE checks below solve to 1e-13 L (≈ 0.1 nm) instead of the default 1e-10 L, so that the
// closure they measure is the agreement of the two formulations, not the solver's stopping rule.
CatenarySolverOptions strict() {
  CatenarySolverOptions o;
  o.tolerance = 1e-13;
  return o;
}

}  // namespace

TEST_CASE("a line resting on the seabed integrates back to its anchor (ODE vs analytic)", "[verification][mooring]") {
  struct Case {
    double friction, x_m, z_m;
    const char* what;
  };
  // OC3-like chain (w, EA of the OC3 deck) at spans that give the three seabed branches.
  const Case cases[] = {{0.0, 848.67, 250.0, "no friction"},
                        {0.5, 848.67, 250.0, "friction, anchor still loaded"},
                        {3.0, 820.0, 250.0, "friction-limited: slack end at the anchor, zero anchor tension"},
                        {1.0, 852.0, 250.0, "nearly lifted off"}};
  for (const Case& c : cases) {
    const CatenaryLine line{902.2, 698.0956, 384.243e6, c.friction, true};
    const CatenarySolution sol = solve_catenary(line, c.x_m, c.z_m, nullptr, strict());
    INFO(c.what);
    REQUIRE(sol.converged);
    REQUIRE(sol.regime == CatenaryRegime::touchdown);
    const OdeResult ode = integrate_down(line, sol, 0.25);
    // RK4 with 0.25 m steps plus a 1e-13 L solve: measured closure and profile error ≤ 1.3e-11 m
    // (touchdown height, anchor position, every grid point); tolerance 10× that, rounded up.
    CHECK(std::abs(ode.touchdown_z_m) <= 3e-10);
    CHECK(std::abs(ode.anchor_m.x()) <= 3e-10);
    CHECK(std::abs(ode.anchor_m.y()) <= 3e-10);
    CHECK(ode.max_profile_error_m <= 3e-10);
    // Anchor tension from the ODE's own friction integration: measured ≤ 3.4e-14 of H.
    CHECK(ode.anchor_h_N == Approx(sol.anchor_h_N).margin(1e-12 * sol.fairlead_h_N));
    if (c.friction == 3.0) {
      CHECK(sol.anchor_h_N == 0.0);  // friction takes the whole horizontal tension
    }
    // Force balance: the suspended length carries V, the seabed friction takes H − H_A.
    // Both hold to rounding (measured ≤ 4e-16).
    CHECK(sol.fairlead_v_N == Approx(line.weight_per_length_N_m * (902.2 - sol.grounded_length_m)).epsilon(1e-12));
    if (sol.anchor_h_N > 0.0 && c.friction > 0.0) {
      CHECK(sol.fairlead_h_N - sol.anchor_h_N ==
            Approx(c.friction * line.weight_per_length_N_m * sol.grounded_length_m).epsilon(1e-12));
    }
  }
}

TEST_CASE("a fully suspended and a taut line integrate back to their anchors", "[verification][mooring]") {
  const CatenaryLine line{902.2, 698.0956, 384.243e6, 1.0, true};
  for (const auto& [x, z] : {std::pair{890.0, 250.0}, std::pair{900.0, 300.0}, std::pair{930.0, 250.0}}) {
    const CatenarySolution sol = solve_catenary(line, x, z, nullptr, strict());
    REQUIRE(sol.converged);
    REQUIRE(sol.regime == CatenaryRegime::suspended);
    const OdeResult ode = integrate_down(line, sol, 0.25);
    CHECK(ode.anchor_m.norm() <= 3e-10);  // measured ≤ 3.4e-11 m; tolerance as above
    CHECK(ode.max_profile_error_m <= 3e-10);
  }
}

TEST_CASE("the inextensible limit is the textbook catenary", "[verification][mooring]") {
  // z(x) = a [cosh((x − x₀)/a) − cosh(x₀/a)], a = H/w, arc length L = a [sinh((X − x₀)/a) + sinh(x₀/a)],
  // V_F = w a sinh((X − x₀)/a). Vertex x₀ left of the anchor (line rising everywhere) and inside
  // the span (sagging below the anchor, no seabed).
  const double w = 1000.0, a = 500.0, span_x = 600.0;
  for (const double x0 : {-100.0, 200.0}) {
    const double length = a * (std::sinh((span_x - x0) / a) + std::sinh(x0 / a));
    const double span_z = a * (std::cosh((span_x - x0) / a) - std::cosh(x0 / a));
    const CatenaryLine line{length, w, 1e20, 0.0, false};  // EA = 1e20 N: stretch ~1e-11 m
    const CatenarySolution sol = solve_catenary(line, span_x, span_z);
    INFO("x0 = " << x0);
    REQUIRE(sol.converged);
    // Default solver tolerance (1e-10 L): measured H, V within 1.2e-12, profile heights within
    // 1.7e-10 m of the cosh curve; tolerances 10× those, rounded up.
    CHECK(sol.fairlead_h_N == Approx(w * a).epsilon(2e-11));
    CHECK(sol.fairlead_v_N == Approx(w * a * std::sinh((span_x - x0) / a)).epsilon(2e-11));
    for (const double s : {0.1 * length, 0.5 * length, 0.9 * length}) {
      const Eigen::Vector2d p = catenary_point(line, sol, s);
      CHECK(p.y() == Approx(a * (std::cosh((p.x() - x0) / a) - std::cosh(x0 / a))).margin(2e-9));
    }
  }
}
