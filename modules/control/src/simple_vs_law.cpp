// ServoDyn's simple variable-speed generator law (VSContrl 1). Standard library only: the test
// DISCON library compiles the law with it.
//
// The documented inputs (ServoDyn input file, "SIMPLE VARIABLE-SPEED TORQUE CONTROL"; OpenFAST docs
// user/servodyn/input.rst): VS_RtGnSp "rated generator speed", VS_RtTq "rated generator
// torque/constant generator torque in Region 3", VS_Rgn2K "generator torque constant in Region 2",
// VS_SlPc "rated generator slip percentage in Region 2 1/2". They describe, on the HSS:
//   region 2     T = k ω²                     for ω < ω_t
//   region 2½    T = S (ω − ω_s)              for ω_t ≤ ω < VS_RtGnSp: an induction machine's line with
//                                             the rated slip, zero torque at the synchronous speed
//                                             ω_s = VS_RtGnSp / (1 + VS_SlPc/100), through VS_RtTq at
//                                             VS_RtGnSp, so S = VS_RtTq / (VS_RtGnSp − ω_s)
//   region 3     T = VS_RtTq                  for ω ≥ VS_RtGnSp
// The transition ω_t is where the line meets the quadratic: k ω² = S (ω − ω_s), i.e.
// k ω² − S ω + S ω_s = 0, roots (S ∓ √(S² − 4 k S ω_s)) / (2k). The lower root is the crossing in
// (ω_s, VS_RtGnSp]: the quadratic lies above the line at ω_s (k ω_s² > 0) and on or below it at
// VS_RtGnSp when k VS_RtGnSp² ≤ VS_RtTq (validate() requires that, else the torque would jump down
// at rated speed), and the upper root lies beyond VS_RtGnSp. Written as
// ω_t = 2 S ω_s / (S + √(S² − 4 k S ω_s)) (the product of the roots is S ω_s / k), it has no
// cancellation for small k and gives ω_t = ω_s for k = 0 (no region-2 torque: the line starts at ω_s,
// below it T = 0).
#include <cmath>
#include <limits>

#include "fowtsim/control/baseline_law.hpp"

namespace fowtsim::control {

SimpleVsCurve simple_vs_curve(const SimpleVsParams& p) {
  SimpleVsCurve c;
  c.synchronous_speed_rad_s = p.rated_generator_speed_rad_s / (1.0 + 0.01 * p.slip_percent);
  c.slope_N_m_s = p.rated_torque_N_m / (p.rated_generator_speed_rad_s - c.synchronous_speed_rad_s);
  const double s = c.slope_N_m_s;
  const double discriminant = s * s - 4.0 * p.region2_gain_N_m_s2 * s * c.synchronous_speed_rad_s;
  c.transition_speed_rad_s = discriminant >= 0.0 ? 2.0 * s * c.synchronous_speed_rad_s / (s + std::sqrt(discriminant))
                                                 : std::numeric_limits<double>::quiet_NaN();
  return c;
}

TorqueRegion simple_vs_region(const SimpleVsParams& p, const SimpleVsCurve& c, double w) {
  if (w >= p.rated_generator_speed_rad_s) return TorqueRegion::region3;
  if (w < c.transition_speed_rad_s) return TorqueRegion::region2;
  return TorqueRegion::region25;
}

double simple_vs_torque(const SimpleVsParams& p, const SimpleVsCurve& c, TorqueRegion region, double w) {
  switch (region) {
    case TorqueRegion::region2: return p.region2_gain_N_m_s2 * w * w;
    case TorqueRegion::region25: return c.slope_N_m_s * (w - c.synchronous_speed_rad_s);
    default: return p.rated_torque_N_m;  // region 3 (the simple law has no regions 1 and 1½)
  }
}

}  // namespace fowtsim::control
