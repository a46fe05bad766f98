// Unit checks of the 2-D catenary: the analytic Jacobian against central differences, the
// solver's round trip on every branch, continuity at the touchdown switch, the H = 0 branches
// in closed form, and the value of a warm start.
#include <cmath>

#include <catch2/catch.hpp>

#include "fowtsim/mooring/catenary.hpp"

using namespace fowtsim::mooring;

namespace {

// An OC3-like chain: w from (77.7066 − 1025 π 0.09²/4) 9.80665.
CatenaryLine chain(double friction, bool seabed = true) {
  return {902.2, 698.0956, 384.243e6, friction, seabed};
}

struct Point {
  double h_N, v_N;
  const char* what;
};

}  // namespace

TEST_CASE("span Jacobian matches central differences on every branch", "[unit][mooring]") {
  const double wl = 698.0956 * 902.2;
  const Point points[] = {{7.4e5, 5.4e5, "touchdown, friction active along the whole grounded part"},
                          {2.0e4, 0.3 * wl, "touchdown, friction-limited (slack end at the anchor)"},
                          {7.4e5, 1.3 * wl, "suspended, anchor pulled up"},
                          {3.0e7, 2.0 * wl, "taut, stretched beyond the unstretched length"},
                          {5.0e5, -0.4 * wl, "suspended below the anchor (no seabed)"}};
  for (const double friction : {0.0, 0.5}) {
    for (const Point& pt : points) {
      const CatenaryLine line = chain(friction, pt.v_N >= 0.0);
      const CatenarySpans sp = catenary_spans(line, pt.h_N, pt.v_N);
      Eigen::Matrix2d fd;
      const double dh = 1e-6 * pt.h_N, dv = 1e-6 * std::abs(pt.v_N);
      const CatenarySpans hp = catenary_spans(line, pt.h_N + dh, pt.v_N), hm = catenary_spans(line, pt.h_N - dh, pt.v_N);
      const CatenarySpans vp = catenary_spans(line, pt.h_N, pt.v_N + dv), vm = catenary_spans(line, pt.h_N, pt.v_N - dv);
      fd << (hp.x_m - hm.x_m) / (2 * dh), (vp.x_m - vm.x_m) / (2 * dv), (hp.z_m - hm.z_m) / (2 * dh),
          (vp.z_m - vm.z_m) / (2 * dv);
      INFO(pt.what << ", C_B = " << friction);
      // Central differences with a 1e-6 relative step: truncation ~1e-12, rounding ~1e-10 of
      // the entries; measured ≤ 7.4e-10 of the largest entry, tolerance 10× that.
      CHECK((sp.jacobian - fd).cwiseAbs().maxCoeff() <= 1e-8 * sp.jacobian.cwiseAbs().maxCoeff());
    }
  }
}

TEST_CASE("the solver recovers the tensions that produced the spans on every branch", "[unit][mooring]") {
  const double wl = 698.0956 * 902.2;
  const Point points[] = {{7.4e5, 5.4e5, "touchdown"},
                          {2.0e4, 0.3 * wl, "friction-limited touchdown"},
                          {7.4e5, 1.3 * wl, "suspended"},
                          {3.0e7, 2.0 * wl, "taut, stretched"},
                          {5.0e2, 0.9 * wl, "nearly slack, almost vertical"},
                          {5.0e5, -0.4 * wl, "suspended below the anchor (no seabed)"}};
  for (const double friction : {0.0, 1.0}) {
    for (const Point& pt : points) {
      const CatenaryLine line = chain(friction, pt.v_N >= 0.0);
      const CatenarySpans sp = catenary_spans(line, pt.h_N, pt.v_N);
      const CatenarySolution sol = solve_catenary(line, sp.x_m, sp.z_m);
      INFO(pt.what << ", C_B = " << friction << ", iterations " << sol.iterations);
      REQUIRE(sol.converged);
      CHECK_FALSE(sol.used_fallback);
      // Residual ≤ 1e-10 L ≈ 0.09 µm; the tensions follow to about that times the line
      // stiffness: measured ≤ 1.5e-9 relative (H) and 3.7e-10 (V); tolerance 10×, rounded up.
      CHECK(sol.fairlead_h_N == Approx(pt.h_N).epsilon(2e-8));
      CHECK(sol.fairlead_v_N == Approx(pt.v_N).epsilon(5e-9));
    }
  }
}

TEST_CASE("spans are continuous where the line lifts off the seabed", "[unit][mooring]") {
  const CatenaryLine line = chain(0.3);
  const double wl = line.weight_per_length_N_m * line.unstretched_length_m;
  const CatenarySpans below = catenary_spans(line, 6e5, wl * (1.0 - 1e-12));
  const CatenarySpans above = catenary_spans(line, 6e5, wl * (1.0 + 1e-12));
  CHECK(below.x_m == Approx(above.x_m).epsilon(1e-11));  // both branches give L_B = 0 at V = w L
  CHECK(below.z_m == Approx(above.z_m).epsilon(1e-11));
  CHECK((below.jacobian - above.jacobian).cwiseAbs().maxCoeff() <= 1e-9 * above.jacobian.cwiseAbs().maxCoeff());
}

TEST_CASE("a slack line over its anchor hangs vertically onto a heap", "[unit][mooring]") {
  // Z = 250 m, X = 100 m: the hanging length l solves Z = l + w l²/(2EA) (≈ 250 m) and
  // X < L − l, so H = 0 and V = w l exactly.
  const CatenaryLine line = chain(1.0);
  const CatenarySolution sol = solve_catenary(line, 100.0, 250.0);
  REQUIRE(sol.converged);
  CHECK(sol.regime == CatenaryRegime::slack_on_seabed);
  CHECK(sol.fairlead_h_N == 0.0);
  const double l = sol.fairlead_v_N / line.weight_per_length_N_m;
  CHECK(l + line.weight_per_length_N_m * l * l / (2 * line.ea_N) == Approx(250.0).epsilon(1e-14));
  CHECK(sol.grounded_length_m == Approx(902.2 - l).epsilon(1e-14));
  CHECK(sol.anchor_h_N == 0.0);
}

TEST_CASE("a line lifted straight up from its anchor stretches elastically", "[unit][mooring]") {
  // Anchor directly below, Z = 910 m > L: vertical taut line, Z = L + (V L − w L²/2)/EA.
  const CatenaryLine line = chain(1.0);
  const CatenarySolution sol = solve_catenary(line, 0.0, 910.0);
  REQUIRE(sol.converged);
  CHECK(sol.regime == CatenaryRegime::vertical);
  const double w = line.weight_per_length_N_m, l = line.unstretched_length_m;
  CHECK(l + (sol.fairlead_v_N * l - w * l * l / 2) / line.ea_N == Approx(910.0).epsilon(1e-14));
  CHECK(sol.anchor_v_N == Approx(sol.fairlead_v_N - w * l).epsilon(1e-14));
}

TEST_CASE("a line without seabed folds into a U when both ends are close", "[unit][mooring]") {
  // Ends at the same height and 0 m apart: each leg hangs half the line, V = w L / 2.
  const CatenaryLine line = chain(0.0, false);
  const CatenarySolution sol = solve_catenary(line, 0.0, 0.0);
  REQUIRE(sol.converged);
  CHECK(sol.fairlead_v_N == Approx(0.5 * line.weight_per_length_N_m * line.unstretched_length_m).epsilon(1e-12));
}

TEST_CASE("a warm start from a nearby solution saves iterations", "[unit][mooring]") {
  const CatenaryLine line = chain(0.001);
  const CatenarySolution first = solve_catenary(line, 848.67, 250.0);
  const CatenaryGuess warm{first.fairlead_h_N, first.fairlead_v_N};
  const CatenarySolution cold = solve_catenary(line, 848.77, 250.02);
  const CatenarySolution hot = solve_catenary(line, 848.77, 250.02, &warm);
  REQUIRE(cold.converged);
  REQUIRE(hot.converged);
  CHECK(hot.iterations < cold.iterations);  // measured: 2 vs 4
  CHECK(hot.fairlead_h_N == Approx(cold.fairlead_h_N).epsilon(1e-9));
}

TEST_CASE("the Peyrot-Goulois guess is positive and finite for slack, taut and vertical spans", "[unit][mooring]") {
  const CatenaryLine line = chain(0.0);
  for (const auto& [x, z] : {std::pair{848.67, 250.0}, std::pair{950.0, 250.0}, std::pair{0.0, 250.0}, std::pair{1e-6, 0.0}}) {
    const CatenaryGuess g = peyrot_goulois_guess(line, x, z);
    CHECK(g.h_N > 0.0);
    CHECK(std::isfinite(g.h_N));
    CHECK(std::isfinite(g.v_N));
  }
}
