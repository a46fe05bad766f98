#pragma once
// Parameters of the hydro module: the platform's hydrodynamic members and the linear extras of the
// deck. Laid out so a YAML `hydro:` section maps onto it key for key (README "Deck mapping").
// Every member is a straight circular cylinder or frustum (taper) fixed in the platform body
// frame b, whose origin is the platform reference point (OpenFAST: SWL on the undisplaced centre
// line). Built once from the deck, validated by validate(); immutable afterwards.
#include <optional>
#include <vector>

#include "fowtsim/core/types.hpp"
#include "fowtsim/hydro/potential_flow.hpp"

namespace fowtsim::hydro {

struct MemberParams {
  Vec3 end_a_body_m = Vec3::Zero();  // end A in the body frame b, from the reference point [m]
  Vec3 end_b_body_m = Vec3::Zero();  // end B in b [m]; the axis runs A → B
  double diameter_a_m = 0.0;         // outer diameter at A [m] (> 0)
  double diameter_b_m = 0.0;         // outer diameter at B [m] (> 0); linear taper in between
  double cd = 0.0;                   // transverse drag coefficient C_d [-] (≥ 0)
  double ca = 0.0;                   // transverse added-mass coefficient C_a [-] (≥ 0); C_m = 1 + C_a
  // End effects (README "End effects"): per end, axial added mass ρ C_a,ax (2/3)π R³, axial drag
  // ½ρ C_d,ax π R² |u_ax| u_ax and the dynamic pressure C_p,ax p π R² on the end plate. Applied
  // only while that end is below the surface.
  double axial_ca_a = 0.0;           // axial added-mass coefficient at end A [-] (≥ 0)
  double axial_cd_a = 0.0;           // axial drag coefficient at end A [-] (≥ 0)
  double axial_cp_a = 1.0;           // dynamic-pressure coefficient on end plate A [-] (≥ 0)
  double axial_ca_b = 0.0;           // the same at end B [-]
  double axial_cd_b = 0.0;           // [-]
  double axial_cp_b = 1.0;           // [-]
  int strips = 10;                   // Morison strips over the submerged part of the axis (≥ 1)
};

// Current added to the wave particle velocity at every strip node (no acceleration).
struct CurrentParams {
  enum class Profile { none, uniform, power_law };
  Profile profile = Profile::none;
  double surface_speed_m_s = 0.0;     // U0 at z = 0 [m/s] (≥ 0)
  double heading_rad = 0.0;           // direction the current flows to, from +x towards +y [rad]
  double reference_depth_m = 0.0;     // power law: U(z) = U0 ((z + d)/d)^p for −d ≤ z ≤ 0, 0 below −d [m]
  double power_law_exponent = 1.0 / 7.0;  // p [-] (> 0); 1/7 is the usual sub-surface current
};

// Where the Morison strips and end effects stop at the top.
enum class SurfaceModel {
  still_water,     // the plane z = 0 (strip theory to SWL, as with linear wave kinematics)
  wave_elevation,  // a horizontal plane at the wave elevation where the member axis meets z = 0,
                   // supplied per member in Input::surface_elevation_m (hydrostatics stay at z = 0)
};

// Where the hydrostatic load comes from.
enum class Hydrostatics {
  nonlinear,  // buoyancy of the members' displaced volume at the instantaneous pose (exact)
  linear,     // ρ g V0 up at the reference point − C_hst q (HydroDyn with WAMIT: PtfmVol0 and the
              // .hst matrix; the centre of buoyancy on the body z axis at rest, as OC3's)
};

// Potential-flow hydrodynamics (issue 15; README "Potential flow"). With it the members carry
// viscous drag only (Morison inertia, Froude–Krylov, end-plate pressure and added mass all come
// from the potential-flow solution, as HydroDyn members with PropPot).
struct PotentialFlowParams {
  RadiationModel radiation;       // A(∞) and the radiation memory
  bool excitation = true;         // add Input::wave_excitation (first-order, from the .3 file)
};

struct Params {
  double water_density_kg_m3 = 1025.0;  // ρ [kg/m³] (> 0)
  double gravity_m_s2 = 9.80665;        // g [m/s²] (> 0)
  std::vector<MemberParams> members;    // at least one
  SurfaceModel surface = SurfaceModel::still_water;
  CurrentParams current;
  // Linear extras about the reference point, inertial frame, DOF order surge, sway, heave, roll,
  // pitch, yaw (OpenFAST HydroDyn AddF0, AddCLin, AddBLin, AddBQuad):
  //   F_add = F0 − C q − B q̇ − B_quad (|q̇| ∘ q̇)
  // with q = [r_ref; Euler 1-2-3 angles] and q̇ = [ṙ_ref; ω] (ω in the inertial frame).
  Vec6 added_force = Vec6::Zero();                 // F0 [N, N·m]
  Mat6 added_stiffness = Mat6::Zero();             // C [N/m, N/rad, N·m/m, N·m/rad]
  Mat6 added_damping = Mat6::Zero();               // B [N/(m/s), N·m/(rad/s), …]
  Mat6 added_quadratic_damping = Mat6::Zero();     // B_quad [N/(m/s)², N·m/(rad/s)², …]
  Hydrostatics hydrostatics = Hydrostatics::nonlinear;
  Mat6 hydrostatic_stiffness = Mat6::Zero();  // linear: C_hst about the reference point [N/m, N·m/rad, …]
  double displaced_volume_m3 = 0.0;           // linear: V0 at rest [m³] (> 0)
  std::optional<PotentialFlowParams> potential_flow;  // absent: Morison strips carry everything
  // Gauss–Legendre points in the axial integral over the part of a member the still-water plane
  // cuts obliquely (hydrostatics.hpp); 16 gives machine precision for the OC3 spar (tests).
  int hydrostatic_quadrature_points = 16;          // [2, 64]
};

// Throws InputError listing every invalid field (member index, key, value, what was expected).
void validate(const Params& params);

// Strip-node layout shared by strip_points() and Input: member m owns `strips` strip midpoints,
// then its end A and end B, starting at node_offset(params, m).
int node_count(const Params& params);
int node_offset(const Params& params, int member);

}  // namespace fowtsim::hydro
