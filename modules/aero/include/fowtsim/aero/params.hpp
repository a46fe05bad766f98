#pragma once
// Parameters of the aero module, laid out so a YAML `aero:` section maps onto them key for key
// (README "Deck mapping"; inputs/nrel5mw/aero.yaml). Angles are radians here, degrees in the deck.
// Built once, checked by validate(), immutable afterwards.
#include <numbers>
#include <vector>

#include "fowtsim/aero/polar.hpp"

namespace fowtsim::aero {

enum class HighInductionCorrection {
  none,  // momentum theory a = κ/(1+κ) at every loading
  buhl,  // Buhl's (2005) Glauert-type empirical C_T(a) above a = 0.4, consistent with the loss factor
};

enum class SkewModel {
  none,         // no redistribution of the induction over the disk (AeroDyn Skew_Mod 0)
  pitt_peters,  // Glauert/Pitt–Peters redistribution a(1 + K (r/R) tan(χ/2) cos ψ) (Skew_Mod 1,
                // SkewRedistr_Mod 1, SkewMomCorr false)
};

// Unsteady airfoil aerodynamics (unsteady_airfoil.hpp). Off: the static polar (quasi-steady).
enum class UnsteadyAirfoilModel {
  none,  // static polar
  hgm,   // Hansen, Gaunaa & Madsen (2004) four-state model (AeroDyn UA_Mod 4)
};

// Dynamic inflow (dynamic_inflow.hpp). Off: the induction of the steady BEM solve (quasi-steady).
enum class DynamicInflowModel {
  none,  // quasi-steady BEM induction
  oye,   // Øye's two-filter model on the induced velocities (AeroDyn DBEMT_Mod 2, continuous)
};

enum class TowerPotential { none, baseline, bak };  // AeroDyn TwrPotent 0, 1, 2
enum class TowerShadow { none, powles, eames };      // AeroDyn TwrShadow 0, 1, 2

// One aerodynamic node of the blade (AeroDyn blade-file row). The blade frame b of a node is the
// coned blade frame without twist and pitch: z_b along the pitch axis toward the tip, x_b normal to
// the coned rotor plane (downwind), y_b = z_b × x_b toward the trailing edge (OpenFAST's blade
// coordinate system). The rigid-rotor helper (rigid_rotor.hpp) places the node from these numbers;
// a flexible-blade driver places it from the beam.
struct BladeNodeParams {
  double span_m = 0.0;           // BlSpn: distance along the pitch axis from the blade root [m]
  double curve_ac_m = 0.0;       // BlCrvAC: offset of the aerodynamic centre along x_b [m]
  double sweep_ac_m = 0.0;       // BlSwpAC: offset of the aerodynamic centre along y_b [m]
  double curve_angle_rad = 0.0;  // BlCrvAng: span axis tilted toward +x_b by this angle [rad]
  double twist_rad = 0.0;        // BlTwist: chord angle to y_b, + turns the leading edge upwind [rad]
  double chord_m = 0.0;          // BlChord [m] (> 0)
  int airfoil = 0;               // BlAFID, 0-based index into Params::airfoils (deck: the name)
};

// Tower axis station for the tower-influence models (AeroDyn TwrElev… table).
struct TowerNodeParams {
  double elevation_m = 0.0;           // distance along the tower axis from the tower reference
                                      // point (Input::tower_base_position_m) [m], increasing
  double diameter_m = 0.0;            // outer diameter [m] (> 0)
  double drag_coefficient = 0.0;      // C_d for the shadow and Bak models [-] (≥ 0)
  double turbulence_intensity = 0.0;  // TI for the Eames shadow [-] (> 0 when Eames is used)
};

struct Params {
  double air_density_kg_m3 = 1.225;   // ρ [kg/m³] (> 0)
  int number_of_blades = 3;           // B (1…10); all blades share `blade`
  std::vector<Polar> airfoils;        // polars, referenced by BladeNodeParams::airfoil
  std::vector<BladeNodeParams> blade; // nodes root → tip (≥ 2, span strictly increasing)

  bool tip_loss = true;                     // Prandtl tip-loss factor (TipLoss)
  bool hub_loss = true;                     // Prandtl hub-loss factor (HubLoss)
  bool tangential_induction = true;         // solve for a' (TanInd)
  bool drag_in_axial_induction = false;     // C_d in the normal coefficient of κ (AIDrag)
  bool drag_in_tangential_induction = false;// C_d in the tangential coefficient of κ' (TIDrag)
  HighInductionCorrection high_induction_correction = HighInductionCorrection::buhl;
  SkewModel skew_model = SkewModel::pitt_peters;
  double skew_factor = 15.0 * std::numbers::pi / 32.0;  // K of the redistribution [-] (≥ 0)
  bool pitching_moment = true;              // apply C_m (UseBlCm)

  // Unsteady models; both off by default (a rotor that does not ask computes none of it). Their
  // states live in Aero::State and are advanced by advance_states().
  UnsteadyAirfoilModel unsteady_airfoil = UnsteadyAirfoilModel::none;
  double ua_pressure_time_constant = 1.5;    // τ_p in units of c/(2W) (HGM; AeroDyn T_p0 = 1.7) (> 0)
  double ua_separation_time_constant = 6.0;  // τ_f in units of c/(2W) (HGM; AeroDyn T_f0 = 3) (> 0)
  double ua_cutout_rad = 45.0 * std::numbers::pi / 180.0;  // static polar beyond |α| (UACutout) (5°…90°)
  DynamicInflowModel dynamic_inflow = DynamicInflowModel::none;
  // The caller's schedule of the quasi-steady induction solve (this module solves when asked):
  // false = at every evaluation; true = a floating scene with rigid or Rayleigh–Ritz blades solves
  // it at a large step's start and holds it over the step's RK4 stages (Aero::Induction::held), as
  // the MBBT coupling holds it over its small steps.
  bool induction_held_over_step = false;

  TowerPotential tower_potential = TowerPotential::none;
  TowerShadow tower_shadow = TowerShadow::none;
  bool tower_drag = false;                  // aerodynamic drag on the tower (AeroDyn TwrAero; tower_drag.hpp)
  std::vector<TowerNodeParams> tower;       // ≥ 2 stations when a tower model is on

  std::vector<int> output_nodes;            // 1-based node numbers of the B<b>N<k>… channels (≤ 9)
};

// Throws InputError listing every invalid field (key, value, what was expected).
void validate(const Params& params);

// Nodes per blade and in the rotor; node k of blade b is column b·nodes_per_blade + k.
inline int nodes_per_blade(const Params& params) { return static_cast<int>(params.blade.size()); }
inline int node_count(const Params& params) {
  return params.number_of_blades * nodes_per_blade(params);
}

}  // namespace fowtsim::aero
