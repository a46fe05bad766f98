#pragma once
// The computations behind the aero verification checks (DESIGN.md §8 tier 2), shared by the module
// tests and `fowtsim verify aero`: the NREL 5MW rotor of OpenFAST's aero_steady runs, its Cp–λ
// peak, azimuth averages of the rotor at an operating point, the momentum balance of converged
// sections, and the tower's potential flow against the cylinder's complex potential. The
// reference values and their sources stay with the callers.
#include <string>
#include <vector>

#include "fowtsim/aero/params.hpp"
#include "fowtsim/aero/rigid_rotor.hpp"

namespace fowtsim::aero::verification {

// Turbine geometry of OpenFAST's aero_steady decks (NRELOffshrBsline5MW_OC3Hywind_ElastoDyn.dat):
// PreCone −2.5° (tips upwind), ShftTilt −5° (nose up), HubRad 1.5 m, OverHang −5.0191 m, TowerHt
// 87.6 m, Twr2Shft 1.96256 m → apex 5.0 m upwind of the tower axis at 90.0 m.
RigidRotor nrel5mw_rigid_rotor();

struct CpPeak {
  double cp = 0.0;   // largest azimuth-averaged RtAeroCp of the Cp–λ curve [-]
  double tsr = 0.0;  // λ = Ω R / RtVAvgxh where it is reached [-]
};
// Peak of the Cp–λ curve at 0° pitch in uniform wind `wind_m_s`: λ = 5…11 in steps of 0.05, each
// point the mean over 12 azimuths of one 120° period; the vertex of the parabola through the best
// sample and its neighbours. Throws NumericalError when the peak is at an end of the sweep.
CpPeak peak_power_coefficient(const Params& params, const RigidRotor& rotor, double wind_m_s);

struct RotorMean {
  double power_W = 0.0;                 // RtAeroPwr [W]
  double thrust_N = 0.0;                // RtAeroFxh [N]
  double torque_N_m = 0.0;              // RtAeroMxh [N·m]
  double cp = 0.0;                      // RtAeroCp [-]
  double ct = 0.0;                      // RtAeroCt [-]
  std::vector<double> alpha_deg;        // (output nodes) blade 1 angle of attack [deg]
  std::vector<double> axial_induction;  // (output nodes) blade 1 axial induction [-]
  int unconverged_evaluations = 0;      // evaluations with a node left without a root (0 expected)
  // Every channel the module writes (Aero::channels, channel_values: names, units and signs as
  // written to the outputs), averaged over the azimuths like the rest.
  std::vector<std::string> channel_names;
  std::vector<double> channel_means;
  // Mean of the named channel; throws InputError for a name the module does not write.
  double channel(const std::string& name) const;
};
// Mean of the rigid rotor's loads and blade-1 output-node states over the azimuths `azimuth_deg`
// (OpenFAST's output rows), uniform wind, rotor speed and pitch as given. Throws InputError for
// an empty azimuth list.
RotorMean rotor_mean(const Params& params, const RigidRotor& rotor, double wind_m_s, double rotor_speed_rpm,
                     double pitch_deg, const std::vector<double>& azimuth_deg);

struct MomentumBalance {
  double worst_thrust = 0.0;  // largest |blade-element thrust / annulus momentum thrust − 1| [-]
  double worst_torque = 0.0;  // same for the torque [-]
  int sections = 0;           // converged sections in the momentum region (a ≤ 0.4) checked
  int failed = 0;             // sections whose solve did not converge (0 expected)
};
// Blade-element loads against the annulus momentum fluxes with the Prandtl factor (Glauert):
//   B q c c_n = 4π r ρ V_x² F a (1 − a),   B q c c_t = 4π r ρ V_x V_y F a' (1 − a),
// drag included in both inductions, on every airfoil node of `params` (from the 5th to the one
// before the tip) at 10 m/s and λ = 4, 6, 8, 10, 0° pitch, hub radius 1.5 m, tip radius 63 m.
// Sections on Buhl's branch (a > 0.4) are not momentum sections and are skipped.
MomentumBalance momentum_balance(Params params);

struct PotentialFlowCheck {
  double worst_m_s = 0.0;  // largest |velocity − complex-potential velocity| over all points [m/s]
  int points = 0;          // points compared
};
// The baseline tower potential (TowerPotential::baseline, no shadow) of a vertical tower of radius
// 3 m in a 10 m/s stream against u − i v = U (1 − R²/z²) of the 2-D cylinder, at 24 angles on
// rings of 1.1, 1.5, 2, 4 and 10 radii, 50 m up a 100 m tower.
PotentialFlowCheck tower_potential_flow();

}  // namespace fowtsim::aero::verification
