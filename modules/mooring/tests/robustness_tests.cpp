// Poses far outside normal operation: finite, physical answers or a clear NumericalError, never
// NaN, never an endless loop (every solver loop has a cap).
#include <algorithm>
#include <cmath>
#include <numbers>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation.hpp"
#include "fowtsim/mooring/presets.hpp"
#include "fowtsim/mooring/profile.hpp"
#include "fowtsim/mooring/stiffness.hpp"

using namespace fowtsim;
using namespace fowtsim::mooring;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

QuasiStaticMooring::Input pose(const Vec3& position, const Vec3& euler_deg) {
  QuasiStaticMooring::Input u;
  u.platform.position_m = position;
  u.platform.orientation = euler123_to_matrix(euler_deg * kDeg);
  return u;
}

bool all_finite(const QuasiStaticMooring::Output& y) {
  bool ok = y.force_N.allFinite() && y.moment_N_m.allFinite();
  for (std::size_t i = 0; i < y.line_count; ++i) {
    const LineOutput& l = y.lines[i];
    ok = ok && std::isfinite(l.fairlead_tension_N) && std::isfinite(l.anchor_tension_N) &&
         std::isfinite(l.fairlead_h_N) && std::isfinite(l.fairlead_v_N) && l.force_N.allFinite();
  }
  return ok;
}

}  // namespace

TEST_CASE("OC3 over a grid of extreme poses: finite answers whose profiles close on the fairleads", "[unit][mooring]") {
  // Surge −200…150 m (upwind line from a slack heap to 14 % stretch), sway, heave −10…+80 m
  // (fairleads above the water), roll/pitch ±30°, yaw ±45°.
  const MooringParams p = oc3_hywind_mooring();
  QuasiStaticMooring::State s = QuasiStaticMooring::make_state(p);
  int poses = 0;
  for (const double surge : {-200.0, -100.0, 0.0, 100.0, 150.0}) {
    for (const double heave : {-10.0, 0.0, 80.0}) {
      for (const double pitch : {-30.0, 0.0, 30.0}) {
        for (const double yaw : {-45.0, 0.0, 45.0}) {
          const auto u = pose(Vec3(surge, 0.3 * surge, heave), Vec3(0.5 * pitch, pitch, yaw));
          const QuasiStaticMooring::Output y = QuasiStaticMooring::evaluate(p, u, s);
          INFO("surge " << surge << " heave " << heave << " pitch " << pitch << " yaw " << yaw);
          REQUIRE(all_finite(y));
          for (std::size_t i = 0; i < 3; ++i) {
            const auto nodes = line_profile(p, u, s, i, 3);
            // Closure = solver residual ≤ 1e-10 L per span (≤ 1.3e-7 m); measured ≤ 8.9e-8 m.
            CHECK((nodes.back().position_m - y.lines[i].fairlead_m).norm() <= 1.3e-7);
            CHECK((nodes.front().position_m - p.lines[i].anchor_m).norm() == 0.0);
            CHECK(y.lines[i].iterations <= 100);
          }
          ++poses;
        }
      }
    }
  }
  CHECK(poses == 135);
}

TEST_CASE("OC3 surge sweep through every regime is continuous, restoring and consistent with K11", "[unit][mooring]") {
  // −250 … +200 m in 0.5 m steps, warm-started: the upwind line goes from a slack heap through
  // touchdown to fully lifted and stretched. The surge force must fall monotonically, and each
  // 0.5 m increment must match the analytic K11 at its ends (mean-value theorem: ΔF/Δx is K11
  // somewhere in between; K11 changes monotonically over 0.5 m) — so no jump at a regime switch.
  const MooringParams p = oc3_hywind_mooring();
  QuasiStaticMooring::State s = QuasiStaticMooring::make_state(p);
  const auto at = [&](double x) { return pose(Vec3(x, 0.0, 0.0), Vec3::Zero()); };
  double previous = QuasiStaticMooring::evaluate(p, at(-250.0), s).force_N.x();
  double k_previous = linearized_stiffness(p, at(-250.0), s)(0, 0);
  bool saw_heap = false, saw_lifted = false;
  for (double x = -249.5; x <= 200.0; x += 0.5) {
    const QuasiStaticMooring::Output y = QuasiStaticMooring::evaluate(p, at(x), s);
    REQUIRE(all_finite(y));
    for (std::size_t i = 0; i < 3; ++i) {
      saw_heap = saw_heap || y.lines[i].regime == CatenaryRegime::slack_on_seabed;
      saw_lifted = saw_lifted || y.lines[i].regime == CatenaryRegime::suspended;
    }
    const double k11 = linearized_stiffness(p, at(x), s)(0, 0);
    const double secant = (previous - y.force_N.x()) / 0.5;
    const double lo = std::min(k_previous, k11), hi = std::max(k_previous, k11);
    INFO("surge " << x << ": secant " << secant << " N/m, K11 " << k_previous << " … " << k11);
    CHECK(y.force_N.x() < previous);
    CHECK(secant >= lo * (1.0 - 1e-6));
    CHECK(secant <= hi * (1.0 + 1e-6));
    previous = y.force_N.x();
    k_previous = k11;
  }
  CHECK(saw_heap);
  CHECK(saw_lifted);
}

TEST_CASE("line pulled taut far beyond its unstretched length stretches elastically", "[unit][mooring]") {
  const MooringParams p = oc3_hywind_mooring();
  QuasiStaticMooring::State s = QuasiStaticMooring::make_state(p);
  const QuasiStaticMooring::Output y = QuasiStaticMooring::evaluate(p, pose(Vec3(-150.0, 0.0, 0.0), Vec3::Zero()), s);
  const LineOutput& l = y.lines[0];  // anchor at +853.87 m: chord ≈ 1029 m vs L = 902.2 m
  CHECK(l.regime == CatenaryRegime::suspended);
  const double chord = (l.fairlead_m - p.lines[0].anchor_m).norm();
  const double straight_tension = 384.243e6 * (chord - 902.2) / 902.2;
  // A nearly straight, heavy line: tension between the weightless spring's and that plus the
  // line's weight w L (698 N/m × 902 m = 0.63 MN).
  CHECK(l.fairlead_tension_N > straight_tension);
  CHECK(l.fairlead_tension_N < straight_tension + 698.1 * 902.2);
  CHECK(l.anchor_v_N > 0.0);  // lifted off the seabed
}

TEST_CASE("slack line with its anchor directly below the fairlead hangs onto a heap", "[unit][mooring]") {
  MooringParams p = oc3_hywind_mooring();
  p.lines.resize(1);
  p.lines[0].anchor_m = Vec3(0.0, 0.0, -320.0);
  p.lines[0].fairlead_body_m = Vec3(0.0, 0.0, -70.0);
  QuasiStaticMooring::State s = QuasiStaticMooring::make_state(p);
  const QuasiStaticMooring::Output y = QuasiStaticMooring::evaluate(p, pose(Vec3::Zero(), Vec3::Zero()), s);
  const double w = apparent_weight_N_m(p, p.lines[0]);
  CHECK(y.lines[0].regime == CatenaryRegime::slack_on_seabed);
  CHECK(y.lines[0].fairlead_h_N == 0.0);
  const double l = y.lines[0].fairlead_v_N / w;  // hanging length: 250 m stretched under its own weight
  CHECK(l + w * l * l / (2.0 * 384.243e6) == Approx(250.0).epsilon(1e-13));
  CHECK(y.lines[0].anchor_tension_N == 0.0);
}

TEST_CASE("a fairlead driven below the seabed is a NumericalError naming the line and the remedy", "[unit][mooring]") {
  const MooringParams p = oc3_hywind_mooring();
  QuasiStaticMooring::State s = QuasiStaticMooring::make_state(p);
  QuasiStaticMooring::Input u = pose(Vec3(0.0, 0.0, -260.0), Vec3::Zero());  // fairleads at z = −330 m
  u.time_s = 12.5;
  try {
    QuasiStaticMooring::evaluate(p, u, s);
    FAIL("expected NumericalError");
  } catch (const NumericalError& e) {
    CHECK(e.context().module == "mooring");
    CHECK(e.context().time_s == 12.5);
    CHECK(e.context().variable.find("line 1") != std::string::npos);
    CHECK(e.message().find("below the seabed") != std::string::npos);
  }
}

TEST_CASE("non-finite poses are a NumericalError, never NaN loads", "[unit][mooring]") {
  const MooringParams p = oc3_hywind_mooring();
  QuasiStaticMooring::State s = QuasiStaticMooring::make_state(p);
  QuasiStaticMooring::Input u;
  u.platform.position_m.x() = std::nan("");
  CHECK_THROWS_AS(QuasiStaticMooring::evaluate(p, u, s), NumericalError);
  CHECK_THROWS_AS(QuasiStaticMooring::advance(p, u, 0.0, 0.1, s), NumericalError);
  u.platform.position_m.x() = 0.0;
  u.platform.orientation(1, 1) = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(QuasiStaticMooring::outputs(p, u, s), NumericalError);
}

TEST_CASE("a poisoned warm start or a one-iteration cap still converges (bisection fallback)", "[unit][mooring]") {
  const CatenaryLine line = catenary_line(oc3_hywind_mooring(), 0);
  const CatenarySolution good = solve_catenary(line, 848.67, 250.0);
  const CatenaryGuess poison{1e-250, 1e250};
  CatenarySolverOptions one;
  one.max_newton_iterations = 1;
  const CatenarySolution a = solve_catenary(line, 848.67, 250.0, &poison);
  const CatenarySolution b = solve_catenary(line, 848.67, 250.0, nullptr, one);
  REQUIRE(a.converged);
  REQUIRE(b.converged);
  CHECK(b.used_fallback);
  CHECK(a.fairlead_h_N == Approx(good.fairlead_h_N).epsilon(1e-8));
  CHECK(b.fairlead_h_N == Approx(good.fairlead_h_N).epsilon(1e-8));  // bisection to the same 1e-10 L residual
  CHECK(b.iterations < 20000);  // bounded: 200 outer × (expansions + 200 inner) at most
}

TEST_CASE("a line lying flat on the seabed: slack heap when short of its length, stretched when pulled",
          "[unit][mooring]") {
  // Fairlead on the seabed (Z = 0): the Jacobian is singular at V = 0, so this exercises the
  // bisection fallback. Pulled 8 m beyond L with C_B = 1: friction builds the tension up from
  // the anchor, X = L + H L/EA − C_B w L²/(2 EA) when the whole line is loaded (s₀ ≤ 0).
  const CatenaryLine line = catenary_line(oc3_hywind_mooring(), 0);
  const CatenaryLine rough{line.unstretched_length_m, line.weight_per_length_N_m, line.ea_N, 1.0, true};
  const CatenarySolution heap = solve_catenary(rough, 800.0, 0.0);
  REQUIRE(heap.converged);
  CHECK(heap.regime == CatenaryRegime::slack_on_seabed);
  CHECK(heap.fairlead_v_N == 0.0);
  const CatenarySolution pulled = solve_catenary(rough, 910.2, 0.0);
  REQUIRE(pulled.converged);
  const double l = rough.unstretched_length_m, w = rough.weight_per_length_N_m, ea = rough.ea_N;
  const double h_hand = (910.2 - l + w * l * l / (2.0 * ea)) * ea / l;
  // With Z = 0, Z grows as V²/(2 H w): the 1e-10 L residual leaves V up to √(2 H w 1e-10 L)
  // ≈ 22 N undetermined, which shifts H by ≈ C_B V (the friction of the lifted bit): 2× that bound.
  const double v_bound = std::sqrt(2.0 * h_hand * w * 1e-10 * l);
  CHECK(pulled.fairlead_v_N <= v_bound);
  CHECK(pulled.fairlead_h_N == Approx(h_hand).margin(2.0 * v_bound));
  CHECK(pulled.anchor_h_N == Approx(h_hand - w * l).margin(2.0 * v_bound));
}
