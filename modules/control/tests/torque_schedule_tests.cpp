// Generator-torque schedule of the NREL 5-MW baseline controller against its published description
// (Jonkman et al., NREL/TP-500-38060, §7.2; constants in ../shared/reference/PUBLISHED.md).
#include <cmath>

#include <catch2/catch.hpp>

#include "fowtsim/control/baseline_controller.hpp"
#include "fowtsim/control/presets.hpp"
#include "fowtsim/control/verification.hpp"

using namespace fowtsim::control;
using fowtsim::control::verification::settled_torque;

TEST_CASE("region 2 torque is k ω² with the published k", "[verification][control]") {
  // Intent: in region 2 the closed controller holds T = VS_Rgn2K ω² (38060 §7.2), k = 2.332287
  // N·m/(rad/s)² on the HSS. Speeds between VS_Rgn2Sp = 91.21 and the 2½ transition (≈ 119 rad/s);
  // the speed is held above rated pitch so the pitch loop stays at 0 (speed < PC_RefSpd).
  const BaselineParams p = nrel5mw_land_baseline();
  const double k = 2.332287;  // PUBLISHED.md "Baseline controller constants"
  for (double w : {92.0, 100.0, 105.0, 110.0, 118.0}) {
    const double torque = settled_torque(p, w);
    INFO("ω = " << w << " rad/s, T = " << torque << " N·m, kω² = " << k * w * w);
    // Tolerance 1e-12 relative: the same closed-form product; the settled filter and rate limit
    // leave only round-off (measured 0 to 2e-16).
    CHECK(std::abs(torque - k * w * w) <= 1e-12 * k * w * w);
  }
}

TEST_CASE("torque regions: boundaries, 1½ and 2½ lines as published", "[verification][control]") {
  // Intent: the schedule of 38060 §7.2 — zero torque up to cut-in (VS_CtInSp 70.16224 rad/s), a
  // line to k ω₂² at VS_Rgn2Sp (91.21091 rad/s), k ω² in region 2, an induction-machine line with
  // 10 % slip (VS_SlPc) through rated power at VS_RtGnSp (121.6805 rad/s) in region 2½, and rated
  // power above. Reference values computed here from the published constants, independently of
  // torque_curve().
  const BaselineParams p = nrel5mw_land_baseline();
  const TorqueCurve c = torque_curve(p);
  const double k = 2.332287, w_ci = 70.16224, w_2 = 91.21091, w_r = 121.6805, power = 5296610.0;
  const double w_sync = w_r / 1.10;                                  // 110.6186 rad/s
  const double slope25 = (power / w_r) / (w_r - w_sync);             // N·m/(rad/s)
  const double slope15 = k * w_2 * w_2 / (w_2 - w_ci);
  // Round-off only: 1e-12 relative (same formulas, different order of operations).
  CHECK(c.synchronous_speed_rad_s == Approx(w_sync).epsilon(1e-12));
  CHECK(c.slope_region25_N_m_s == Approx(slope25).epsilon(1e-12));
  CHECK(c.slope_region15_N_m_s == Approx(slope15).epsilon(1e-12));
  // Region 2 meets the 2½ line at the transition speed: k ω_t² = S₂½ (ω_t − ω_s), and ω_t lies in
  // (ω₂, ω_rated) (38060 Fig. 7-2). Round-off: 1e-9 relative of the torque (the root loses digits
  // to cancellation in S − √(S² − 4kSω_s)).
  const double wt = c.transition_speed_rad_s;
  CHECK(wt > w_2);
  CHECK(wt < w_r);
  CHECK(k * wt * wt == Approx(slope25 * (wt - w_sync)).epsilon(1e-9));

  const auto torque = [&](double w) { return scheduled_torque(p, c, torque_region(p, c, w, 0.0), w); };
  CHECK(torque(60.0) == 0.0);                                   // region 1
  CHECK(torque(w_ci) == 0.0);
  CHECK(torque(80.0) == Approx(slope15 * (80.0 - w_ci)).epsilon(1e-12));  // region 1½
  CHECK(torque(std::nextafter(w_2, 0.0)) == Approx(k * w_2 * w_2).epsilon(1e-12));  // continuous at ω₂
  CHECK(torque(120.0) == Approx(slope25 * (120.0 - w_sync)).epsilon(1e-12));         // region 2½
  CHECK(torque(std::nextafter(w_r, 0.0)) == Approx(power / w_r).epsilon(1e-12));     // continuous at rated
  CHECK(torque_region(p, c, 100.0, 0.0) == TorqueRegion::region2);
  CHECK(torque_region(p, c, 120.0, 0.0) == TorqueRegion::region25);
  CHECK(torque_region(p, c, w_r, 0.0) == TorqueRegion::region3);
  // Region 3 also whenever the pitch is at or above VS_Rgn3MP = 1° (38060 §7.2).
  CHECK(torque_region(p, c, 100.0, 0.01745329) == TorqueRegion::region3);
}

TEST_CASE("region 3: constant power (land) or constant torque (OC3), capped at VS_MaxTq", "[verification][control]") {
  // Intent: above rated the land-based controller holds P = T ω_f = VS_RtPwr (38060 §7.2); the OC3
  // variant holds the rated torque VS_RtPwr / PC_RefSpd (TP-500-47266 §7). Both never exceed
  // VS_MaxTq = 47,402.91 N·m.
  const BaselineParams land = nrel5mw_land_baseline();
  const BaselineParams oc3 = oc3_hywind_baseline();
  for (double w : {123.0, 126.0, 130.0}) {
    const double pitch = 0.1;  // above VS_Rgn3MP: region 3
    // 1e-12 relative: closed form, settled filter and rate limit.
    CHECK(settled_torque(land, w, pitch) * w == Approx(5296610.0).epsilon(1e-12));
    CHECK(settled_torque(oc3, w, pitch) == Approx(5296610.0 / 122.9096).epsilon(1e-12));
  }
  // The OpenFAST v5 OC3 run with the OC3 DISCON writes GenTq = 43.0935440 kN·m in region 3
  // (openfast-runs/oc3_spar_wturb_wavesirr, t ≥ 23.55 s). Tolerance 2e-7 relative: the DISCON returns
  // the torque through the float32 swap array (ulp 0.004 N·m at 43 kN·m, 9e-8 relative) and the
  // .out prints 9 digits.
  CHECK(torque_curve(oc3).rated_torque_N_m == Approx(43093.5440).epsilon(2e-7));
  // Constant power at a low speed with the pitch above VS_Rgn3MP asks more than the limit: capped.
  CHECK(settled_torque(land, 100.0, 0.1) == 47402.91);
}
