#pragma once
// Rigid multibody of a floating wind turbine (seed 000 §4.4.1, DESIGN.md §4 "large step"):
// platform + rigid tower, nacelle on a (fixed or prescribed) yaw bearing, hub + rotor with the
// azimuth DOF, drivetrain with optional torsional flexibility. The module contract of DESIGN.md §2
// with one deviation: advance() takes a LoadProvider instead of an Input, because the hydro and
// mooring loads depend on the pose and must be re-evaluated at every Runge–Kutta stage; outputs()
// takes the AppliedLoads at the state (the accelerations and internal loads depend on them).
#include <array>
#include <vector>

#include "fowtsim/core/channels.hpp"
#include "fowtsim/core/interface.hpp"
#include "fowtsim/multibody/dynamics.hpp"
#include "fowtsim/multibody/loads.hpp"
#include "fowtsim/multibody/model.hpp"
#include "fowtsim/multibody/state.hpp"

namespace fowtsim::multibody {

inline constexpr int kChannelCount = 42;       // channels of the rigid-tower model
inline constexpr int kTowerChannelCount = 2;   // TTDspFA, TTDspSS, appended with a flexible tower
inline constexpr int kGaugeChannelCount = 8;   // TwHt{k}FL{x,y,z}t, ML{x,y,z}t, TD{x,y}t per tower gauge, appended next
// Then TwrClrnc1 … B with rigid or Rayleigh–Ritz blades (the MBBT blades' tips are not the multibody's),
// then per Rayleigh–Ritz blade RootF/M{x,y,z}{c,b}, TipD{x,y}{c,b}, OoPDefl, IPDefl and its gauges'
// Spn{k}FL/ML{x,y,z}b.
inline constexpr int kRrBladeChannelCount = 18;
inline constexpr int kBladeGaugeChannelCount = 6;
inline constexpr int kMaxChannelCount = kChannelCount + kTowerChannelCount + kMaxTowerGauges * kGaugeChannelCount + kMaxBlades +
                                        kMaxBlades * (kRrBladeChannelCount + kMaxBladeGauges * kBladeGaugeChannelCount);

struct Output {
  GeneralisedVector acceleration = GeneralisedVector::Zero();  // u̇ (model.hpp Dof order) [m/s², rad/s²]
  Vec3 platform_angles_rad = Vec3::Zero();        // Euler 1-2-3 (roll, pitch, yaw) of T_gb, θ2 ∈ [−π/2, π/2] [rad]
  Vec3 platform_acceleration_m_s2 = Vec3::Zero(); // a_r in g [m/s²]
  Vec3 platform_angular_acceleration_rad_s2 = Vec3::Zero();  // α in g [rad/s²]
  Vec6 tower_base_loads = Vec6::Zero();   // [F; M] of everything above on the tower base, about it, frame t (= b axes) [N, N·m]
  Vec6 yaw_bearing_loads = Vec6::Zero();  // [F; M] of nacelle + rotor on the tower top, about it, frame p (= b axes) [N, N·m]
  std::array<FrameMotion, kMaxBlades> blade_root{};  // motion of each blade-root frame r_i (model.hpp)
  std::array<Vec6, kMaxBlades> blade_root_loads{};   // Rayleigh–Ritz blades: [F; M] of blade i on the hub, about its root, g [N, N·m]
  FrameMotion hub;                        // rotating hub frame h at the apex
  std::array<double, kMaxChannelCount> channels{};  // values of channels(), same order and units (the first channels().size())
};

struct Multibody {
  // The state at the model's initial conditions.
  static State make_state(const Model& model) { return initial_state(model); }

  // Advances `state` from t to t + dt by classical RK4 in ceil(dt / max_step_s) equal substeps,
  // calling provider.loads() (and nacelle_yaw() when prescribed) at every stage. The attitude
  // quaternion is integrated (q̇ = ½ q ⊗ (0, ω_b)) and renormalised after each substep. Allocates
  // nothing; throws NumericalError (module, time, variable, hint) on a non-finite result.
  static void advance(const Model& model, LoadProvider& provider, double t, double dt, State& state);

  // Accelerations, internal loads, blade-root motions and channel values at `state` under `loads`
  // (the loads the provider returns at this state). Pure.
  static Output outputs(const Model& model, const AppliedLoads& loads, const State& state, double t = 0.0);

  // PtfmSurge … YawBrMzp: OpenFAST names, output units (deg, rpm, kN, kN·m).
  static std::vector<ChannelInfo> channels(const Model& model);
};

}  // namespace fowtsim::multibody
