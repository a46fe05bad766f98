#pragma once
// Parameters of the built-in controller: by default the NREL 5-MW baseline controller (Jonkman et al., NREL/TP-500-38060, 2009, Ch. 7):
// a single-pole low-pass filter on the generator speed, a variable-speed generator-torque schedule
// (regions 1, 1½, 2, 2½, 3) with torque and torque-rate limits, and a gain-scheduled PI collective
// blade-pitch controller with pitch-angle and pitch-rate limits. Either law can be swapped for one
// of ServoDyn's simple modes: the simple variable-speed generator law (VSContrl 1) and no pitch
// control (PCMode 0). Each member maps one to one onto a
// key of the deck section `controller:` (inputs/nrel5mw/controller_land.yaml). Speeds are on the
// high-speed (generator) shaft, angles in radians, SI everywhere (DESIGN.md §3).
//
// This header and baseline_law.hpp depend on the standard library only, so the test DISCON shared
// library (tests/discon/) can compile the very same law.
#include <string_view>

namespace fowtsim::control {

// Generator torque above rated (38060 §7.3: constant power; TP-500-47266 §7 OC3-Hywind: constant
// torque, to avoid the negative damping of the platform-pitch mode).
enum class Region3Torque {
  constant_power,   // T = P_rated / ω_f
  constant_torque,  // T = P_rated / ω_ref (the rated torque)
};

// "constant_power" | "constant_torque" → Region3Torque; throws InputError naming the key otherwise.
Region3Torque region3_torque_from_name(std::string_view name);
const char* region3_torque_name(Region3Torque mode);

// Which generator-torque law runs (OpenFAST ServoDyn's VSContrl, NREL/TP-500-38060 §7.2).
enum class GeneratorLaw {
  baseline,   // the 38060 schedule below (regions 1–3, filter, torque and rate limits): a DISCON, VSContrl 5
  simple_vs,  // ServoDyn's simple variable-speed law (VSContrl 1): SimpleVsParams, on the measured speed
};
// Which blade-pitch law runs (ServoDyn's PCMode).
enum class PitchLaw {
  baseline,  // the gain-scheduled PI of 38060 §7.3 (a DISCON, PCMode 5)
  fixed,     // no pitch control (PCMode 0): every blade held at its pitch at the first call
};

// "baseline" | "simple_vs" and "baseline" | "fixed"; InputError naming the key otherwise.
GeneratorLaw generator_law_from_name(std::string_view name);
PitchLaw pitch_law_from_name(std::string_view name);

// ServoDyn's simple variable-speed generator law (VSContrl 1; inputs as documented in the ServoDyn
// input file, "SIMPLE VARIABLE-SPEED TORQUE CONTROL", and OpenFAST docs user/servodyn/input.rst).
// ServoDyn takes speeds in rpm and VS_Rgn2K in N·m/rpm²; here rad/s and N·m/(rad/s)² like the rest
// of the section: k[N·m/(rad/s)²] = VS_Rgn2K[N·m/rpm²] × (30/π)². No default: all four are given.
struct SimpleVsParams {
  double rated_generator_speed_rad_s = 0.0;  // VS_RtGnSp: rated generator speed, HSS [rad/s]
  double rated_torque_N_m = 0.0;             // VS_RtTq: rated / constant region-3 torque, HSS [N·m]
  double region2_gain_N_m_s2 = 0.0;          // VS_Rgn2K: k in T = k ω² [N·m/(rad/s)²]
  double slip_percent = 0.0;                 // VS_SlPc: rated slip of the region-2½ line [%]
};

// Closed-form quantities of the simple law (derivation in simple_vs_law.cpp).
struct SimpleVsCurve {
  double synchronous_speed_rad_s = 0.0;  // ω_s = VS_RtGnSp / (1 + VS_SlPc/100): zero torque of the 2½ line
  double slope_N_m_s = 0.0;              // S = VS_RtTq / (VS_RtGnSp − ω_s) [N·m/(rad/s)]
  double transition_speed_rad_s = 0.0;   // ω_t: region 2 → 2½, lower root of k ω² = S (ω − ω_s)
};

struct BaselineParams {
  // --- which laws run (the baseline ones by default) -----------------------------------------------
  GeneratorLaw generator = GeneratorLaw::baseline;
  PitchLaw pitch = PitchLaw::baseline;
  SimpleVsParams simple_vs{};  // used only with generator = simple_vs

  // --- timing ------------------------------------------------------------------------------------
  double sample_time_s = 0.0;  // controller sample time [s], ≥ 0; 0 = update at every call (DISCON DT)

  // --- generator-speed filter (38060 §7.1) --------------------------------------------------------
  double filter_corner_rad_s = 1.570796;  // corner frequency ω_c of the single-pole low-pass [rad/s] (0.25 Hz)

  // --- variable-speed torque (38060 §7.2), generator (HSS) side ------------------------------------
  double cut_in_speed_rad_s = 70.16224;          // VS_CtInSp: region 1 → 1½ [rad/s]
  double region2_start_speed_rad_s = 91.21091;   // VS_Rgn2Sp: region 1½ → 2 [rad/s]
  double region2_gain_N_m_s2 = 2.332287;         // VS_Rgn2K: k in T = k ω² [N·m/(rad/s)²]
  double rated_generator_speed_rad_s = 121.6805; // VS_RtGnSp: top of region 2½ [rad/s]
  double rated_power_W = 5296610.0;              // VS_RtPwr: rated mechanical power [W]
  double slip_percent = 10.0;                    // VS_SlPc: slip of the 2½ induction-machine line [%]
  double max_torque_N_m = 47402.91;              // VS_MaxTq: torque limit [N·m]
  double max_torque_rate_N_m_s = 15000.0;        // VS_MaxRat: torque-rate limit [N·m/s]
  double region3_min_pitch_rad = 0.01745329;     // VS_Rgn3MP: pitch beyond which region 3 holds [rad]
  Region3Torque region3_torque = Region3Torque::constant_power;  // torque law above rated

  // --- collective pitch (38060 §7.3) --------------------------------------------------------------
  double reference_speed_rad_s = 122.9096;       // PC_RefSpd: regulated generator speed [rad/s]
  double proportional_gain_s = 0.01882681;       // PC_KP at zero pitch [rad/(rad/s)] = [s]
  double integral_gain = 0.008068634;            // PC_KI at zero pitch [rad/rad] = [-]
  double gain_schedule_pitch_rad = 0.1099965;    // PC_KK: pitch at which the gains are halved [rad]
  double min_pitch_rad = 0.0;                    // PC_MinPit [rad]
  double max_pitch_rad = 1.570796;               // PC_MaxPit [rad], ≥ min_pitch_rad (equal: pitch held there)
  double max_pitch_rate_rad_s = 0.1396263;       // PC_MaxRat: |dθ/dt| limit [rad/s] (8°/s)

  // --- electrical -------------------------------------------------------------------------------
  double generator_efficiency = 0.944;  // η: electrical / mechanical power [-] (38060 Table 1-1), for GenPwr
};

// Closed-form quantities of the torque schedule that follow from the parameters (38060 §7.2).
struct TorqueCurve {
  double synchronous_speed_rad_s = 0.0;   // ω_s = ω_rated,gen / (1 + slip/100): zero-torque point of the 2½ line
  double slope_region15_N_m_s = 0.0;      // region 1½ line through (ω_cut-in, 0) and (ω_2, k ω_2²) [N·m/(rad/s)]
  double slope_region25_N_m_s = 0.0;      // region 2½ line through (ω_s, 0) and (ω_rated,gen, P/ω_rated,gen)
  double transition_speed_rad_s = 0.0;    // region 2 → 2½: lower root of k ω² = S₂½ (ω − ω_s) [rad/s]
  double rated_torque_N_m = 0.0;          // P_rated / ω_ref: constant-torque region-3 value [N·m]
};

// The simple law's curve of p (no check; validate() rejects parameters without a 2/2½ crossing).
SimpleVsCurve simple_vs_curve(const SimpleVsParams& p);

// Rated generator speed of the generator law in use (VS_RtGnSp of the baseline or of the simple law) [rad/s].
double rated_speed_of_law_rad_s(const BaselineParams& p);

// The torque curve of p; NaN members when p has no region-2/2½ intersection (validate() rejects that).
TorqueCurve torque_curve(const BaselineParams& p);

// Collects every problem (key, value found, what was expected) and throws one InputError listing
// them all (module "control"); returns normally when the parameters are usable.
void validate(const BaselineParams& p);

}  // namespace fowtsim::control
