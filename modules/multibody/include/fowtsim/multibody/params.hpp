#pragma once
// Parameters of the rigid multibody of a floating wind turbine: platform + rigid tower (the base
// body), nacelle on a yaw bearing, hub + rotor on the low-speed shaft, drivetrain. Field names
// are the keys of a deck's `structure:` section one to one (README "Deck mapping"), with the
// unit in the key name (io/schema.hpp) — so angles stay in degrees here, as in the deck, and
// are converted once in make_model(). Numbers follow the ElastoDyn inputs they are named after.
//
// Frames (OpenFAST, DESIGN.md §3): g inertial (origin at SWL on the undisplaced centre line, x
// downwind, z up); b platform body frame, origin at the platform reference point, parallel to g
// when the platform is undisplaced; the tower is straight along z_b.
#include <array>
#include <optional>
#include <vector>

#include "fowtsim/core/types.hpp"
#include "fowtsim/flexbody/elastodyn_blade.hpp"

namespace fowtsim::multibody {

struct PlatformParams {
  double mass_kg = 0.0;                   // PtfmMass [kg] (≥ 0)
  Vec3 cm_m = Vec3::Zero();               // (PtfmCMxt, PtfmCMyt, PtfmCMzt): CM from SWL, in b [m]
  double roll_inertia_kg_m2 = 0.0;        // PtfmRIner, about the CM, x_b [kg·m²] (≥ 0)
  double pitch_inertia_kg_m2 = 0.0;       // PtfmPIner, about the CM, y_b [kg·m²] (≥ 0)
  double yaw_inertia_kg_m2 = 0.0;         // PtfmYIner, about the CM, z_b [kg·m²] (≥ 0)
  double xy_inertia_kg_m2 = 0.0;          // PtfmXYIner = −∫xy dm about the CM [kg·m²]
  double yz_inertia_kg_m2 = 0.0;          // PtfmYZIner = −∫yz dm [kg·m²]
  double xz_inertia_kg_m2 = 0.0;          // PtfmXZIner = −∫xz dm [kg·m²]
  double reference_height_m = 0.0;        // PtfmRefzt: platform reference point above SWL [m]
};

// Rigid tower, merged into the base body: a straight line mass along z_b (ElastoDyn, like the
// deck, gives no tower torsional inertia). Mass per length is piecewise linear between stations
// and integrated exactly (mass_model.cpp).
struct TowerParams {
  double base_height_m = 0.0;             // TowerBsHt: tower base above SWL [m]
  double top_height_m = 0.0;              // TowerHt: tower top (yaw bearing) above SWL [m] (> base)
  std::vector<double> station_fraction;   // HtFract: 0 … 1 along the tower, strictly increasing [-]
  std::vector<double> mass_density_kg_m;  // TMassDen at the stations [kg/m] (≥ 0)
  double mass_density_scale = 1.0;        // AdjTwMa: factor on TMassDen [-] (≥ 0)
  // Flexible tower (ElastoDyn TwFADOF1/2, TwSSDOF1/2): off by default, the rigid tower above.
  // The number of modes per direction is the number of shape rows (0 … 2 each).
  bool flexible = false;
  std::vector<double> fore_aft_stiffness_N_m2;             // TwFAStif at the stations [N·m²] (> 0)
  std::vector<double> side_side_stiffness_N_m2;            // TwSSStif at the stations [N·m²] (> 0)
  std::vector<std::vector<double>> fore_aft_mode_shapes;   // TwFAM{1,2}Sh(2 … 6): 5 coefficients per mode
  std::vector<std::vector<double>> side_side_mode_shapes;  // TwSSM{1,2}Sh(2 … 6)
  std::vector<double> fore_aft_damping_percent;            // TwrFADmp per mode [% of critical]
  std::vector<double> side_side_damping_percent;           // TwrSSDmp per mode [%]
  // Tower gauges (ElastoDyn NTwGages/TwrGagNd): heights above the tower base along the undeflected
  // axis, 0 ≤ h < top − base, at most 9 (TwHt1 … TwHt9 channels). ElastoDyn's gauge node J of its
  // TwrNodes equal elements sits at h = (J − ½)(TowerHt − TowerBsHt)/TwrNodes (OC3: J 10 of 20 →
  // 36.86 m). With the rigid tower the gauges give the rigid tower's loads, as ElastoDyn's do with
  // its tower DOFs off.
  std::vector<double> gauge_heights_m;                     // [m]
};

struct NacelleParams {
  double mass_kg = 0.0;                   // NacMass [kg] (≥ 0)
  Vec3 cm_m = Vec3::Zero();               // (NacCMxn, NacCMyn, NacCMzn) from the tower top, nacelle frame [m]
  double yaw_inertia_kg_m2 = 0.0;         // NacYIner about the yaw axis (not the CM) [kg·m²]
  double yaw_bearing_mass_kg = 0.0;       // YawBrMass, a point mass at the tower top [kg] (≥ 0)
  Vec3 imu_m = Vec3::Zero();              // (NcIMUxn, NcIMUyn, NcIMUzn) from the tower top [m]
  double tower_to_shaft_m = 0.0;          // Twr2Shft: tower top to the shaft axis, vertical [m]
  double overhang_m = 0.0;                // OverHang: yaw axis to rotor apex along the shaft [m] (< 0 upwind)
  double shaft_tilt_deg = 0.0;            // ShftTilt (ElastoDyn sign: < 0 raises the upwind end) [deg], |·| < 90
  bool yaw_prescribed = false;            // false: yaw fixed at initial_conditions; true: LoadProvider::nacelle_yaw(t)
};

// Hub and rotor. Rigid blades are lumped by their mass moments about the root along the preconed
// pitch axis (a line mass, as ElastoDyn's blade mass distribution); blade_mass_moments() turns
// an ElastoDyn distributed-mass table into these three numbers.
struct RotorParams {
  int blade_count = 3;                    // NumBl (1 … 3)
  double hub_mass_kg = 0.0;               // HubMass [kg] (≥ 0)
  double hub_inertia_kg_m2 = 0.0;         // HubIner about the shaft axis [kg·m²] (≥ 0)
  double hub_cm_m = 0.0;                  // HubCM: apex to hub CM along the shaft, + downwind [m]
  double hub_radius_m = 0.0;              // HubRad: apex to blade root along the preconed axis [m] (≥ 0)
  double tip_radius_m = 0.0;              // TipRad [m] (> hub radius); documentation and checks only
  double precone_deg = 0.0;               // PreCone (ElastoDyn sign: < 0 cones the blades upwind) [deg]
  bool flexible_blades = false;           // true: blades are not in the rotor body, their root loads come in
  double blade_mass_kg = 0.0;             // one blade's mass [kg] (≥ 0; rigid blades only)
  double blade_first_mass_moment_kg_m = 0.0;    // ∫ m r dr about the root [kg·m] (rigid only)
  double blade_second_mass_moment_kg_m2 = 0.0;  // ∫ m r² dr about the root [kg·m²] (rigid only)
  // Rayleigh–Ritz blades (ElastoDyn's FlapDOF1, FlapDOF2, EdgeDOF): each blade a flexible body with
  // ElastoDyn's flap 1, flap 2 and edge 1 shapes (flexbody/blade_shapes.hpp) on the hub, instead of
  // the rigid mass moments above. Its hub and tip radius must equal the rotor's.
  std::optional<flexbody::ElastoDynBlade> rayleigh_ritz_blade;
  int rayleigh_ritz_blade_nodes = 17;     // BldNodes: ElastoDyn's midpoint rule for the blade's integrals (≥ 1)
  // Spans from the root where the blades' points are wanted (the aerodynamic nodes), ascending;
  // the tip is added as the last station [m].
  std::vector<double> blade_station_spans_m;
  // Rayleigh–Ritz blade gauges (ElastoDyn's NBlGages/BldGagNd, ≤ 9): span fractions x/L from the
  // root, for the Spn{k}FL/ML{x,y,z}b{b} channels [-].
  std::vector<double> blade_gauge_fractions;
};

struct DrivetrainParams {
  double gearbox_ratio = 1.0;             // GBRatio: HSS speed / LSS speed [-] (> 0)
  double generator_inertia_kg_m2 = 0.0;   // GenIner about the HSS [kg·m²] (≥ 0)
  bool torsional_flexibility = false;     // DrTrDOF: rotor and generator azimuths are two DOFs
  double torsional_stiffness_N_m_rad = 0.0;    // DTTorSpr on the LSS [N·m/rad] (≥ 0)
  double torsional_damping_N_m_s_rad = 0.0;    // DTTorDmp on the LSS [N·m/(rad/s)] (≥ 0)
};

// Initial conditions (ElastoDyn "INITIAL CONDITIONS"); angles Euler 1-2-3 roll, pitch, yaw.
struct InitialConditions {
  Vec3 platform_position_m = Vec3::Zero();        // (PtfmSurge, PtfmSway, PtfmHeave) [m], g
  Vec3 platform_angles_deg = Vec3::Zero();        // (PtfmRoll, PtfmPitch, PtfmYaw) [deg]
  Vec3 platform_velocity_m_s = Vec3::Zero();      // reference-point velocity in g [m/s]
  Vec3 platform_angular_velocity_deg_s = Vec3::Zero();  // ω in the body frame b [deg/s]
  double azimuth_deg = 0.0;               // Azimuth: blade 1 up at 0, + about the shaft axis (downwind) [deg]
  double rotor_speed_rpm = 0.0;           // RotSpeed [rpm]; negative spins backwards
  double nacelle_yaw_deg = 0.0;           // NacYaw [deg] (fixed yaw, or start of a prescribed one)
  std::array<double, 2> tower_top_deflection_m{};  // TTDspFA, TTDspSS: put on the 1st FA / SS mode (ElastoDyn); flexible tower only [m]
  double blade_pitch_deg = 0.0;           // BlPitch [deg]: every blade's, held until the controller's first call
                                          // (the rotor aerodynamics and the flexible blades take it; the chain does not)
  // Rayleigh–Ritz blades start undeflected (ElastoDyn's OoPDefl = IPDefl = 0) or at their static
  // deflection under gravity, the aerodynamic loads and the spin of the initial state (the scene
  // settles them; other blades ignore it: MBBT blades have `blades.start`).
  bool rayleigh_ritz_blades_static = false;
};

// Which DOFs a load case frees (ElastoDyn's PtfmSgDOF … GenDOF switches). A held platform DOF
// keeps its initial value (its velocity starts and stays zero: the seed's "fixed" cases hold the
// platform at given angles). The rotor spin is free (the rotor row of the equations of motion),
// held at its initial speed (GenDOF off), or prescribed: azimuth, speed and acceleration of rotor
// and generator come from LoadProvider::rotor_spin(t) because the flexible-blade coupling solves
// the spin together with the blades at the small step (DESIGN.md §4: the blades carry ≈ 7× the
// rotational inertia of hub and generator, so the spin must not receive their torque explicitly).
enum class RotorSpin { free, held, prescribed };
struct DofSwitches {
  std::array<bool, 6> platform_free{true, true, true, true, true, true};  // surge, sway, heave, roll, pitch, yaw
  RotorSpin rotor = RotorSpin::free;
};

struct Params {
  double gravity_m_s2 = 9.80665;          // g [m/s²] (≥ 0); switched per evaluation by AppliedLoads::gravity
  double max_step_s = 0.02;               // largest internal RK4 step of advance() [s] (> 0)
  PlatformParams platform;
  TowerParams tower;
  NacelleParams nacelle;
  RotorParams rotor;
  DrivetrainParams drivetrain;
  InitialConditions initial_conditions;
  DofSwitches dofs;
};

// Blade mass, first and second mass moments about the root of a line mass whose mass per length
// is piecewise linear between stations (ElastoDyn blade file: BlFract, BMassDen × AdjBlMs), blade
// length = tip − hub radius. Exact integration of the piecewise-linear density.
struct BladeMassMoments {
  double mass_kg = 0.0;
  double first_moment_kg_m = 0.0;
  double second_moment_kg_m2 = 0.0;
};
BladeMassMoments blade_mass_moments(const std::vector<double>& span_fraction,
                                    const std::vector<double>& mass_density_kg_m,
                                    double mass_density_scale, double blade_length_m);

}  // namespace fowtsim::multibody
