// Free rigid multibody (no gravity, no damping, no external loads) with a spinning rotor:
// energy and angular momentum are invariants of the exact solution; and the gyroscopic
// precession of a spinning rotor on a pitching base against the linearised gyrostat solution.
#include <cmath>

#include <catch2/catch.hpp>

#include "fowtsim/multibody/verification.hpp"

using namespace fowtsim;
using namespace fowtsim::multibody;
using verification::Drift;
using verification::free_run_drift;
using verification::gyroscopic_precession;
using verification::Precession;

TEST_CASE("free OC3 multibody conserves energy and momentum over 1000 rotor revolutions",
          "[verification][multibody][conservation]") {
  // 1000 revolutions at 12.1 rpm = 4959 s of platform tumbling + rotor spin + drivetrain torsion
  // (2.2 Hz), RK4 at the large step 0.02 s used by seed 000 §4.5.3.
  const Drift d = free_run_drift(12.1, 1000.0, 0.02);
  WARN("12.1 rpm: energy " << d.energy << ", angular momentum " << d.angular << ", linear " << d.linear);
  CHECK(d.energy < 1e-6);   // brief: 1e-6 relative over 1000 revolutions
  CHECK(d.angular < 1e-6);  // brief: 1e-6 relative
  CHECK(d.linear < 1e-12);  // RK4 preserves linear invariants exactly: round-off only
}

TEST_CASE("reverse rotor spin and a 90° pitched platform conserve energy and momentum",
          "[verification][multibody][conservation][robustness]") {
  const Drift reverse = free_run_drift(-12.1, 200.0, 0.02);
  // 90° platform pitch: Euler 1-2-3 gimbal lock; the quaternion attitude has none.
  const Drift locked = free_run_drift(12.1, 200.0, 0.02, Vec3(0.0, 90.0, 0.0));
  WARN("reverse: " << reverse.energy << " " << reverse.angular << "; 90 deg: " << locked.energy << " " << locked.angular);
  CHECK(reverse.energy < 1e-6);  // same tolerances as the 1000-revolution case
  CHECK(reverse.angular < 1e-6);
  CHECK(locked.energy < 1e-6);
  CHECK(locked.angular < 1e-6);
}

TEST_CASE("gyroscopic precession of a spinning rotor on a pitching base", "[verification][multibody][gyroscopic]") {
  // Ω = ±10 rad/s (h = ±1e7 N·m·s), M = 1e3 N·m: precession M/h = ±1e-4 rad/s, nutation period
  // 88.9 s. The linearisation neglects terms of relative size ~ pitch angle ~ I3 M / h² = 1e-3.
  for (const double rpm : {95.49296585513721, -95.49296585513721}) {
    const Precession small = gyroscopic_precession(rpm, 1.0e3);
    const Precession large = gyroscopic_precession(rpm, 1.0e4);
    WARN("rpm " << rpm << ": precession " << small.mean_rate << " rad/s vs analytic " << small.mean_rate_exact
         << ", rel " << std::abs(small.mean_rate / small.mean_rate_exact - 1) << "; rate error/(M/h) "
         << small.worst_rate << " (M = 1e3), " << large.worst_rate << " (M = 1e4)");
    // Tolerance 2e-3 = 2 × the neglected relative size I3 M / h² (the bound, not a fit).
    CHECK(small.mean_rate == Approx(small.mean_rate_exact).epsilon(2e-3));
    CHECK(small.worst_rate < 2e-3);
    CHECK(small.mean_rate * rpm > 0.0);  // the precession follows the spin direction
    // The residual is the linearisation: it grows linearly with M (×10 → ×10; ±20 % allowed).
    CHECK(large.worst_rate / small.worst_rate == Approx(10.0).epsilon(0.2));
  }
}
