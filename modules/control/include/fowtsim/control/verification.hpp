#pragma once
// The plant and loops behind the controller's verification checks (DESIGN.md §8 tier 2), shared by
// the module tests and `fowtsim verify control`. The reference values and their sources stay with
// the callers.
//
// Plant: a rigid NREL 5-MW rotor whose aerodynamic torque follows the quasi-steady power
// coefficient Cp(λ, θ), on a rigid drivetrain:
//   J Ω̇ = Q_aero − N T_gen,  Q_aero = ½ ρ π R² U³ Cp(λ, θ) / Ω,  λ = Ω R / U.
// Cp: the NREL-5MW rotor performance table of the ROSCO toolbox (NREL/ROSCO repository,
// Test_Cases/NREL-5MW/Cp_Ct_Cq.NREL5MW.txt, written 10 Jan 2022 by CCBlade BEM), rows λ = 3.0…8.5,
// columns θ = −5…24.5°, bilinear interpolation (src/cp_table.inc). The aero module is not used
// (modules depend on core only); the driver's coupled runs close this loop with real aerodynamics.
#include <functional>

#include "fowtsim/control/baseline_controller.hpp"

namespace fowtsim::control::verification {

struct Rotor {
  double air_density_kg_m3 = 1.225;   // aero_steady README (AeroDyn AirDens of the OC3 deck)
  double radius_m = 63.0;             // tip radius (ElastoDyn TipRad)
  double gearbox_ratio = 97.0;        // ElastoDyn GBRatio
  // LSS inertia: rotor 38,677,040.6 kg·m² (ElastoDyn summary of the OC3 run) + N² × generator
  // 534.116 kg·m² (ElastoDyn GenIner).
  double inertia_kg_m2 = 38677040.613 + 97.0 * 97.0 * 534.116;

  // Cp at tip-speed ratio λ and pitch θ [deg]; throws InputError outside the table.
  double power_coefficient(double tsr, double pitch_deg) const;
  // Q_aero [N·m] at wind U [m/s], rotor speed Ω [rad/s], pitch θ [rad].
  double aero_torque_N_m(double wind_m_s, double rotor_speed_rad_s, double pitch_rad) const;
};

// θ [deg] on the falling branch of Cp(λ, ·) (above its peak, up to 24.5°) where Cp = `cp`.
double pitch_for_cp_deg(const Rotor& r, double tsr, double cp);

// θ [rad] at which the rotor absorbs `power_W` at wind U and rotor speed Ω (Cp falling branch,
// bisection over θ ∈ [0, 24.5°]): the steady pitch of an ideal above-rated controller.
double equilibrium_pitch_rad(const Rotor& r, double wind_m_s, double rotor_speed_rad_s, double power_W);

struct LoopSample {
  double time_s = 0.0;
  double wind_m_s = 0.0;
  double rotor_speed_rad_s = 0.0;      // Ω at the sample
  ControllerOutput demand;             // controller output held over [t, t + dt]
};

// Closed loop controller + rotor at step dt from t = 0 to t_end, ideal pitch actuator (measured
// pitch = last demand), RK4 on the drivetrain with the demands held over each step. `observe`
// sees every sample. Controller is BaselineController or ExternalController.
template <class Controller>
void run_loop(const Rotor& rotor, const typename Controller::Params& p, typename Controller::State& s,
              const std::function<double(double)>& wind_m_s, double initial_rotor_speed_rad_s,
              double initial_pitch_rad, double dt, double t_end, const std::function<void(const LoopSample&)>& observe);

struct SteadyLoop {
  double pitch_deg = 0.0;        // mean blade-1 pitch demand over the last 20 s [deg]
  double rotor_speed_rpm = 0.0;  // mean rotor speed over the last 20 s [rpm]
  double pitch_drift_deg = 0.0;  // max − min of the pitch demand over the last 20 s [deg]
};
// The baseline controller on `rotor` in constant wind from 12.1 rpm and 0° pitch at the OC3 deck's
// large step 0.0125 s until t_end (> 20 s), averaged over the last 20 s.
SteadyLoop settle_closed_loop(const Rotor& rotor, const BaselineParams& p, double wind_m_s, double t_end_s);

// Torque demand of the baseline controller after holding the generator speed `w` for 60 s at
// 0.0125 s (the filter's time constant 0.64 s and the 15 kN·m/s rate limit have settled), with the
// measured pitch `pitch_rad` on all blades [N·m].
double settled_torque(const BaselineParams& p, double generator_speed_rad_s, double pitch_rad = 0.0);

// Largest |ω_f − (110 − 10 exp(−ω_c t))| / 110 of the baseline controller's speed filter seeded at
// 100 rad/s and fed 110 rad/s at the uneven call intervals 0.01, 0.0125, 0.03, 0.2 and 0.5 s: the
// filter's departure from the exact step response of a single pole at ω_c = p.filter_corner_rad_s.
double filter_step_response_error(const BaselineParams& p);

}  // namespace fowtsim::control::verification
