#pragma once
// The NREL 5-MW baseline control law as a discrete-time system (Jonkman et al., NREL/TP-500-38060,
// Ch. 7; OC3-Hywind variant NREL/TP-500-47266 §7). Pure functions on plain data, standard library
// only: the built-in controller (baseline_controller.hpp) and the test DISCON shared library run
// this same code, so the DLL path can be checked against the built-in path.
//
// Timing (the DISCON "LastTime" logic): every call filters the generator speed over the time since
// the previous call; the torque and pitch demands are recomputed only when at least one sample time
// has elapsed since the last update and are held in between (zero-order hold). With a caller step
// ΔT ≥ T_s the law updates at every call with the elapsed time ΔT; with ΔT < T_s it updates every
// ⌈T_s/ΔT⌉-th call, with the actual elapsed time. Times are absolute simulation times [s].
#include <array>

#include "fowtsim/control/baseline_params.hpp"

namespace fowtsim::control {

inline constexpr int kBladeCount = 3;

// Variable-speed torque region (38060 §7.2), for diagnostics and tests.
enum class TorqueRegion { region1, region15, region2, region25, region3 };

struct BaselineState {
  bool initialised = false;                // false until the first call seeds filter and integrator
  double filtered_speed_rad_s = 0.0;       // ω_f: low-pass filtered generator speed [rad/s]
  double speed_error_integral_rad = 0.0;   // ∫(ω_f − ω_ref) dt, anti-windup clamped [rad]
  double last_call_time_s = 0.0;           // time of the previous call (filter step) [s]
  double last_update_time_s = 0.0;         // time of the last torque/pitch update [s]
  double torque_demand_N_m = 0.0;          // held generator-torque demand, HSS [N·m]
  std::array<double, kBladeCount> pitch_demand_rad{};  // held blade-pitch demands, blades 1–3 [rad]
  TorqueRegion region = TorqueRegion::region1;         // region of the last torque update
};

struct Measurements {
  double generator_speed_rad_s = 0.0;                  // ω: generator (HSS) speed [rad/s]
  std::array<double, kBladeCount> blade_pitch_rad{};   // measured blade pitch angles [rad]
};

// Gain-scheduling factor G_K = 1 / (1 + θ/θ_K) (38060 §7.3: the pitch sensitivity of aerodynamic
// power grows about linearly with pitch, doubling at θ_K).
double gain_correction(const BaselineParams& p, double pitch_rad);

// Region of the torque schedule at filtered speed ω_f with last pitch demand θ (38060 §7.2):
// region 3 when ω_f ≥ ω_rated,gen or θ ≥ θ_Rgn3MP; otherwise by speed.
TorqueRegion torque_region(const BaselineParams& p, const TorqueCurve& c, double filtered_speed_rad_s,
                           double pitch_rad);

// Torque of the schedule before the rate limit, capped at the maximum torque [N·m].
double scheduled_torque(const BaselineParams& p, const TorqueCurve& c, TorqueRegion region,
                        double filtered_speed_rad_s);

// Region of ServoDyn's simple variable-speed law at the measured generator speed ω: region 3 when
// ω ≥ VS_RtGnSp, region 2 below the transition speed, region 2½ between (simple_vs_law.cpp).
TorqueRegion simple_vs_region(const SimpleVsParams& p, const SimpleVsCurve& c, double generator_speed_rad_s);

// Torque of the simple law in that region [N·m]: k ω², S (ω − ω_s) or VS_RtTq; no limits, no filter.
double simple_vs_torque(const SimpleVsParams& p, const SimpleVsCurve& c, TorqueRegion region,
                        double generator_speed_rad_s);

// One call of the law at time `time_s` with the measurements `m`. The first call seeds the filter
// with the measured speed, the held pitch demands with the measured pitches and the integrator so
// that the integral term reproduces the measured blade-1 pitch (no bump), and sets the torque from
// the schedule without rate limit. A call at a time not after the previous one changes nothing.
// With p.generator = simple_vs the torque is ServoDyn's simple law at the measured speed at every
// update (no filter, no rate limit: VSContrl 1 has none); with p.pitch = fixed the pitch demands
// stay at the first call's measured pitch and the integrator is not used (PCMode 0).
// Does not check finiteness (the caller does).
void baseline_update(const BaselineParams& p, const TorqueCurve& c, const Measurements& m, double time_s,
                     BaselineState& s);

}  // namespace fowtsim::control
