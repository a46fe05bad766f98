// Kane's spin-up beam (seed 002 Sec. 5.2) across two modules: flexbody's Rayleigh–Ritz beam
// against the MBBT finite-volume beam of modules/beam and against modules/beam's own RR reference
// (verify/kane_spin_up.hpp; `fowtsim verify flexbody` runs the same). The MBBT beam is
// geometrically exact, so it plays the role of the seed's nonlinear lumped-mass reference.
#include <catch2/catch.hpp>

#include "verify/kane_spin_up.hpp"

using namespace fowtsim::driver;

TEST_CASE("Kane's spin-up (seed 002 Sec. 5.2): flexbody RR with 1 and 3 modes vs the MBBT beam",
          "[verification]") {
  const KaneSpinUp h = kane_spin_up_histories();
  REQUIRE(h.mbbt.size() == h.rr1.size());
  REQUIRE(h.mbbt.size() == h.rr3.size());
  const double e1 = rms_over_max(h.rr1, h.mbbt), e3 = rms_over_max(h.rr3, h.mbbt);
  INFO("max |tip| MBBT " << max_abs(h.mbbt) << " m, RR-1 " << max_abs(h.rr1) << " m, RR-3 " << max_abs(h.rr3)
                         << " m; RMS difference / max |tip|: 1 mode " << e1 << ", 3 modes " << e3);
  // The seed finds 0.5 % (1 shape) and 0.3 % (3 shapes) relative RMS against its nonlinear
  // lumped-mass code; the MBBT beam is likewise geometrically exact, so the seed's figures are the
  // bounds. The RR drops terms of order slope² ≈ (0.57/10)² ≈ 0.3 % and the MBBT carries its own
  // O(h², Δt²) error (< 0.1 %, modules/beam README), so nothing tighter is justified.
  // Measured 0.40 % (1 mode) and 0.052 % (3 modes).
  CHECK(e1 < 0.005);
  CHECK(e3 < 0.003);

  // modules/beam's kane_rayleigh_ritz_tip is the same model (eq. 26 stiffening, eq. 32 modes, RK4
  // at 1 ms) coded separately with Simpson quadrature and its own β_j and hub profile. Both take
  // the same RK4 steps, so only the quadratures (< 1e-12 relative each) and rounding separate
  // them: bounded at 1e-10 of the deflection (measured 6.7e-15 m, 1.2e-14).
  REQUIRE(h.rr3.size() == h.beam_rr3.size());
  const double diff = max_abs_difference(h.rr3, h.beam_rr3);
  INFO("max |difference| " << diff << " m of max |tip| " << max_abs(h.beam_rr3) << " m");
  CHECK(diff < 1e-10 * max_abs(h.beam_rr3));
}
