// ServoDyn's simple modes in the built-in controller: the simple variable-speed generator law
// (VSContrl 1) against its closed form, and no pitch control (PCMode 0) holding the pitch.
#include <cmath>
#include <numbers>

#include <catch2/catch.hpp>

#include "fowtsim/control/baseline_controller.hpp"
#include "fowtsim/core/error.hpp"

using namespace fowtsim::control;

namespace {

constexpr double kRpm = std::numbers::pi / 30.0;  // rad/s per rpm

// The NREL 5MW in the simple variable-speed mode, as FAST's NREL 5MW decks with VSContrl 1 give it
// (VS_RtGnSp 1173.7 rpm, VS_RtTq 43093.55 N·m, VS_Rgn2K 0.0255764 N·m/rpm², VS_SlPc 10 %; also
// inputs/nrel5mw/controller_simple_vs.yaml), converted to the deck's SI units.
SimpleVsParams nrel5mw_simple_vs() {
  return {1173.7 * kRpm, 43093.55, 0.0255764 / (kRpm * kRpm), 10.0};
}

BaselineParams with_simple_modes(const SimpleVsParams& v) {
  BaselineParams p;
  p.generator = GeneratorLaw::simple_vs;
  p.pitch = PitchLaw::fixed;
  p.simple_vs = v;
  p.integral_gain = 0.0;  // unused with a fixed pitch: must not be required
  return p;
}

// Torque of the built-in controller at generator speed w, held over one step after a first call
// at another speed: the simple law has neither filter nor rate limit, so the second call is the law.
double controller_torque(const BaselineParams& p, double w) {
  auto s = BaselineController::make_state(p);
  ControllerInput u;
  u.generator_speed_rad_s = 0.5 * w;
  BaselineController::advance(p, u, 0.0, 0.0125, s);
  u.generator_speed_rad_s = w;
  BaselineController::advance(p, u, 0.0125, 0.0125, s);
  return BaselineController::outputs(p, u, s).generator_torque_N_m;
}

// The crossing of k ω² and the 2½ line, found by bisection on (ω_s, ω_rated], independently of the
// closed-form root in simple_vs_law.cpp.
double crossing_by_bisection(const SimpleVsParams& v, double w_sync) {
  const double slope = v.rated_torque_N_m / (v.rated_generator_speed_rad_s - w_sync);
  auto gap = [&](double w) { return v.region2_gain_N_m_s2 * w * w - slope * (w - w_sync); };
  double lo = w_sync, hi = v.rated_generator_speed_rad_s;  // gap(lo) > 0 ≥ gap(hi)
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (gap(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST_CASE("simple VS law: the three regions and the transition speed from the quadratic", "[unit][control]") {
  // Intent: region 2 T = k ω² below ω_t, region 2½ T = S (ω − ω_s) with ω_s = VS_RtGnSp/(1 + VS_SlPc/100)
  // and S = VS_RtTq/(VS_RtGnSp − ω_s), region 3 T = VS_RtTq from VS_RtGnSp on (ServoDyn input
  // descriptions), each through the controller's own outputs.
  const SimpleVsParams v = nrel5mw_simple_vs();
  const BaselineParams p = with_simple_modes(v);
  const double w_r = v.rated_generator_speed_rad_s, k = v.region2_gain_N_m_s2;
  const double w_sync = w_r / 1.10;  // 10 % slip
  const double slope = v.rated_torque_N_m / (w_r - w_sync);
  const SimpleVsCurve c = simple_vs_curve(v);
  // Same formulas, different association: round-off only (1e-13 relative).
  CHECK(c.synchronous_speed_rad_s == Approx(w_sync).epsilon(1e-13));
  CHECK(c.slope_N_m_s == Approx(slope).epsilon(1e-13));
  // Closed-form root vs 200 bisections (interval below 1 ulp): 1e-12 relative. For the 5MW numbers
  // ω_t = 1150.88 rpm (120.52 rad/s), between ω_s = 1067.0 rpm and rated 1173.7 rpm.
  const double w_t = crossing_by_bisection(v, w_sync);
  CHECK(c.transition_speed_rad_s == Approx(w_t).epsilon(1e-12));
  CHECK(c.transition_speed_rad_s > w_sync);
  CHECK(c.transition_speed_rad_s < w_r);
  INFO("ω_t = " << c.transition_speed_rad_s / kRpm << " rpm");
  // Region 2, 2½, 3 at speeds inside each; the law is a single product or line: 1e-12 relative.
  for (double w : {20.0, 70.0, 100.0, 0.999 * w_t}) {
    CHECK(controller_torque(p, w) == Approx(k * w * w).epsilon(1e-12));
  }
  for (double f : {0.01, 0.5, 0.99}) {
    const double w = w_t + f * (w_r - w_t);
    CHECK(controller_torque(p, w) == Approx(slope * (w - w_sync)).epsilon(1e-12));
  }
  for (double w : {w_r, 1.001 * w_r, 1.3 * w_r}) CHECK(controller_torque(p, w) == v.rated_torque_N_m);
}

TEST_CASE("simple VS law is continuous at both transitions", "[unit][control]") {
  // Intent: no torque jump where region 2 meets 2½ (the crossing) nor where 2½ meets region 3 (the
  // line reaches VS_RtTq at VS_RtGnSp). First the neighbouring pieces at the boundary itself (equal
  // to round-off, 1e-12 relative), then the controller's torque either side by a relative 1e-9 in
  // speed: the steepest piece, the 2½ line, has a relative slope ω_r/(ω_r − ω_s) = 1 + 100/VS_SlPc = 11,
  // so an honest step changes T by ≤ 2.2e-8 T; 1e-7 catches any jump above 4 mN·m.
  const SimpleVsParams v = nrel5mw_simple_vs();
  const BaselineParams p = with_simple_modes(v);
  const SimpleVsCurve c = simple_vs_curve(v);
  const double w_t = c.transition_speed_rad_s, w_r = v.rated_generator_speed_rad_s;
  CHECK(simple_vs_torque(v, c, TorqueRegion::region2, w_t) == Approx(simple_vs_torque(v, c, TorqueRegion::region25, w_t)).epsilon(1e-12));
  CHECK(simple_vs_torque(v, c, TorqueRegion::region25, w_r) == Approx(simple_vs_torque(v, c, TorqueRegion::region3, w_r)).epsilon(1e-12));
  for (double w : {w_t, w_r}) {
    const double below = controller_torque(p, w * (1.0 - 1e-9)), above = controller_torque(p, w * (1.0 + 1e-9));
    INFO("boundary " << w << " rad/s: " << below << " → " << above << " N·m");
    CHECK(std::abs(above - below) <= 1e-7 * above);
  }
}

TEST_CASE("simple VS law: the edge cases of its inputs", "[unit][control]") {
  SimpleVsParams v = nrel5mw_simple_vs();
  SECTION("k = 0: no region-2 torque, the 2½ line starts at the synchronous speed") {
    v.region2_gain_N_m_s2 = 0.0;
    const SimpleVsCurve c = simple_vs_curve(v);
    CHECK(c.transition_speed_rad_s == Approx(c.synchronous_speed_rad_s).epsilon(1e-15));
    const BaselineParams p = with_simple_modes(v);
    CHECK(controller_torque(p, 0.9 * c.synchronous_speed_rad_s) == 0.0);
    CHECK(controller_torque(p, 0.5 * (c.synchronous_speed_rad_s + v.rated_generator_speed_rad_s)) ==
          Approx(0.5 * v.rated_torque_N_m).epsilon(1e-12));
  }
  SECTION("k ω_rated² = VS_RtTq: the quadratic meets the line at rated speed, no region 2½") {
    v.region2_gain_N_m_s2 = v.rated_torque_N_m / (v.rated_generator_speed_rad_s * v.rated_generator_speed_rad_s);
    CHECK(simple_vs_curve(v).transition_speed_rad_s == Approx(v.rated_generator_speed_rad_s).epsilon(1e-12));
    CHECK_NOTHROW(validate(with_simple_modes(v)));
  }
  SECTION("k ω_rated² > VS_RtTq would drop the torque at rated speed: rejected, naming the key") {
    v.region2_gain_N_m_s2 *= 1.5;  // 5MW: k ω_r² = 34,532 N·m; ×1.5 = 51,800 > 43,094
    REQUIRE(v.region2_gain_N_m_s2 * v.rated_generator_speed_rad_s * v.rated_generator_speed_rad_s > v.rated_torque_N_m);
    CHECK_THROWS_WITH(validate(with_simple_modes(v)), Catch::Contains("controller.simple_vs.region2_gain_N_m_s2"));
  }
  SECTION("non-positive slip, rated speed or torque, negative k: rejected, naming the key") {
    SimpleVsParams bad = v;
    bad.slip_percent = 0.0;
    CHECK_THROWS_WITH(validate(with_simple_modes(bad)), Catch::Contains("controller.simple_vs.slip_percent"));
    bad = v;
    bad.rated_torque_N_m = -1.0;
    CHECK_THROWS_WITH(validate(with_simple_modes(bad)), Catch::Contains("controller.simple_vs.rated_torque_N_m"));
    bad = v;
    bad.rated_generator_speed_rad_s = 0.0;
    CHECK_THROWS_WITH(validate(with_simple_modes(bad)), Catch::Contains("controller.simple_vs.rated_generator_speed_rad_s"));
    bad = v;
    bad.region2_gain_N_m_s2 = -1e-3;
    CHECK_THROWS_WITH(validate(with_simple_modes(bad)), Catch::Contains("controller.simple_vs.region2_gain_N_m_s2"));
  }
}

TEST_CASE("GenPwr of the simple law is torque × measured speed × efficiency", "[unit][control]") {
  BaselineParams p = with_simple_modes(nrel5mw_simple_vs());
  p.generator_efficiency = 0.944;
  auto s = BaselineController::make_state(p);
  ControllerInput u;
  u.generator_speed_rad_s = 100.0;
  BaselineController::advance(p, u, 0.0, 0.0125, s);
  const ControllerOutput y = BaselineController::outputs(p, u, s);
  CHECK(y.generator_torque_N_m == Approx(p.simple_vs.region2_gain_N_m_s2 * 1e4).epsilon(1e-14));
  CHECK(y.generator_power_W == Approx(y.generator_torque_N_m * 100.0 * 0.944).epsilon(1e-14));
}

TEST_CASE("pitch fixed (PCMode 0): every blade keeps its first measured pitch, exactly", "[unit][control]") {
  // Intent: no pitch controller — 100 s far above rated speed (the baseline PI would feather) with
  // the measured pitch wandering: the demands stay bit for bit at the first call's pitches; the
  // gains are not needed (integral_gain 0 is accepted), and the torque law still runs.
  for (GeneratorLaw law : {GeneratorLaw::simple_vs, GeneratorLaw::baseline}) {
    BaselineParams p = with_simple_modes(nrel5mw_simple_vs());
    p.generator = law;
    auto s = BaselineController::make_state(p);
    ControllerInput u;
    u.blade_pitch_rad = {0.05, 0.06, 0.07};
    const auto initial = u.blade_pitch_rad;
    for (int i = 0; i <= 8000; ++i) {
      const double t = 0.0125 * i;
      u.generator_speed_rad_s = 150.0;
      u.blade_pitch_rad = {0.05 + 0.01 * std::sin(t), 0.06, 0.07 - 0.01 * std::sin(t)};
      BaselineController::advance(p, u, t, 0.0125, s);
      REQUIRE(BaselineController::outputs(p, u, s).blade_pitch_rad == initial);
    }
    CHECK(s.torque_demand_N_m > 0.0);
  }
  BaselineParams baseline_pitch;  // the baseline PI still needs its integral gain
  baseline_pitch.integral_gain = 0.0;
  CHECK_THROWS_WITH(validate(baseline_pitch), Catch::Contains("controller.integral_gain"));
}

TEST_CASE("simple VS torque with the baseline pitch loop: the PI still feathers above rated", "[unit][control]") {
  // Intent: the two choices are independent — VSContrl 1 with a pitch controller (PCMode 5 in
  // OpenFAST with a DISCON) holds VS_RtTq above rated while the PI pitches.
  BaselineParams p = with_simple_modes(nrel5mw_simple_vs());
  p.pitch = PitchLaw::baseline;
  p.integral_gain = BaselineParams{}.integral_gain;
  auto s = BaselineController::make_state(p);
  ControllerInput u;
  u.generator_speed_rad_s = 130.0;  // above PC_RefSpd 122.9 rad/s
  for (int i = 0; i <= 800; ++i) BaselineController::advance(p, u, 0.0125 * i, 0.0125, s);
  CHECK(s.pitch_demand_rad[0] > 0.0);
  CHECK(s.torque_demand_N_m == p.simple_vs.rated_torque_N_m);
}
