#include "fowtsim/multibody/oc3.hpp"

namespace fowtsim::multibody {

Params oc3_hywind_params() {
  Params p;
  p.gravity_m_s2 = 9.80665;
  p.max_step_s = 0.02;
  // ElastoDyn: PtfmMass, PtfmCMzt, PtfmRIner/PIner/YIner, PtfmRefzt.
  p.platform.mass_kg = 7466330.0;
  p.platform.cm_m = Vec3(0.0, 0.0, -89.9155);
  p.platform.roll_inertia_kg_m2 = 4.22923e9;
  p.platform.pitch_inertia_kg_m2 = 4.22923e9;
  p.platform.yaw_inertia_kg_m2 = 1.6423e8;
  p.platform.reference_height_m = 0.0;
  // ElastoDyn: TowerBsHt, TowerHt; ElastoDyn_Tower.dat: HtFract, TMassDen, AdjTwMa.
  p.tower.base_height_m = 10.0;
  p.tower.top_height_m = 87.6;
  p.tower.station_fraction = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
  p.tower.mass_density_kg_m = {4667.0, 4345.28, 4034.76, 3735.44, 3447.32, 3170.4,
                               2904.69, 2650.18, 2406.88, 2174.77, 1953.87};
  p.tower.mass_density_scale = 1.0;
  // ElastoDyn: NacMass, NacCM*n, NacYIner, YawBrMass, NcIMU*n, Twr2Shft, OverHang, ShftTilt.
  p.nacelle.mass_kg = 240000.0;
  p.nacelle.cm_m = Vec3(1.9, 0.0, 1.75);
  p.nacelle.yaw_inertia_kg_m2 = 2607890.0;
  p.nacelle.yaw_bearing_mass_kg = 0.0;
  p.nacelle.imu_m = Vec3(-3.09528, 0.0, 2.23336);
  p.nacelle.tower_to_shaft_m = 1.96256;
  p.nacelle.overhang_m = -5.0191;
  p.nacelle.shaft_tilt_deg = -5.0;
  // ElastoDyn: NumBl, HubMass, HubIner, HubCM, HubRad, TipRad, PreCone; blades per 38060 Table 2-1.
  p.rotor.blade_count = 3;
  p.rotor.hub_mass_kg = 56780.0;
  p.rotor.hub_inertia_kg_m2 = 115926.0;
  p.rotor.hub_cm_m = 0.0;
  p.rotor.hub_radius_m = 1.5;
  p.rotor.tip_radius_m = 63.0;
  p.rotor.precone_deg = -2.5;
  p.rotor.flexible_blades = false;
  p.rotor.blade_mass_kg = 17740.0;
  p.rotor.blade_first_mass_moment_kg_m = 363231.0;
  p.rotor.blade_second_mass_moment_kg_m2 = 11776047.0;
  // ElastoDyn: GBRatio, GenIner, DrTrDOF, DTTorSpr, DTTorDmp.
  p.drivetrain.gearbox_ratio = 97.0;
  p.drivetrain.generator_inertia_kg_m2 = 534.116;
  p.drivetrain.torsional_flexibility = true;
  p.drivetrain.torsional_stiffness_N_m_rad = 867637000.0;
  p.drivetrain.torsional_damping_N_m_s_rad = 6215000.0;
  return p;
}

void set_oc3_flexible_tower(Params& p) {
  TowerParams& t = p.tower;
  t.flexible = true;
  t.fore_aft_stiffness_N_m2 = {6.03903e11, 5.17644e11, 4.40925e11, 3.73022e11, 3.13236e11, 2.60897e11,
                               2.15365e11, 1.76028e11, 1.42301e11, 1.1363e11, 8.9488e10};
  t.side_side_stiffness_N_m2 = t.fore_aft_stiffness_N_m2;
  t.fore_aft_mode_shapes = {{0.8689, 0.2205, -0.0908, 0.1167, -0.1154},
                            {42.5859, -18.6419, -20.357, -23.2686, 20.6816}};
  t.side_side_mode_shapes = {{0.834, 0.2216, -0.0571, 0.0934, -0.0918},
                             {60.2285, -27.5868, -30.3887, -33.6738, 32.4208}};
  t.fore_aft_damping_percent = {1.0, 1.0};
  t.side_side_damping_percent = {1.0, 1.0};
}

}  // namespace fowtsim::multibody
