#pragma once
// Test plant for the controller: a rigid NREL 5-MW rotor whose aerodynamic torque follows the
// quasi-steady power coefficient Cp(λ, θ), on a rigid drivetrain:
//   J Ω̇ = Q_aero − N T_gen,  Q_aero = ½ ρ π R² U³ Cp(λ, θ) / Ω,  λ = Ω R / U.
// Cp: the NREL-5MW rotor performance table of the ROSCO toolbox (NREL/ROSCO repository,
// Test_Cases/NREL-5MW/Cp_Ct_Cq.NREL5MW.txt, written 10 Jan 2022 by CCBlade BEM), rows λ = 3.0…8.5,
// columns θ = −5…24.5°, bilinear interpolation. The aero module is not used (modules depend on
// core only); the driver's coupled runs will close this loop with real aerodynamics.
#include <array>
#include <functional>
#include <vector>

#include "fowtsim/control/baseline_controller.hpp"

namespace fowtsim::control::testing {

struct Rotor {
  double air_density_kg_m3 = 1.225;   // aero_steady README (AeroDyn AirDens of the OC3 deck)
  double radius_m = 63.0;             // tip radius (ElastoDyn TipRad)
  double gearbox_ratio = 97.0;        // ElastoDyn GBRatio
  // LSS inertia: rotor 38,677,040.6 kg·m² (ElastoDyn summary of the OC3 run) + N² × generator
  // 534.116 kg·m² (ElastoDyn GenIner).
  double inertia_kg_m2 = 38677040.613 + 97.0 * 97.0 * 534.116;

  // Cp at tip-speed ratio λ and pitch θ [deg]; throws std::out_of_range outside the table.
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

}  // namespace fowtsim::control::testing
