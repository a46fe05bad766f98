#include "decks/structure_deck.hpp"

#include "decks/deck_helpers.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

using io::Schema;

namespace {

Schema non_negative(const char* doc) { return Schema::number().at_least(0.0).doc(doc); }
Schema any_number(const char* doc) { return Schema::number().doc(doc); }
Schema zero_default(const char* doc) { return Schema::number().default_value(0.0).doc(doc); }

}  // namespace

Schema structure_schema() {
  const Schema platform = Schema::map({
      {"mass_kg", non_negative("PtfmMass")},
      {"cm_m", number_vector(3, "platform CM from SWL, body frame (PtfmCMxt, PtfmCMyt, PtfmCMzt)")},
      {"roll_inertia_kg_m2", non_negative("PtfmRIner, about the CM")},
      {"pitch_inertia_kg_m2", non_negative("PtfmPIner, about the CM")},
      {"yaw_inertia_kg_m2", non_negative("PtfmYIner, about the CM")},
      {"xy_inertia_kg_m2", zero_default("PtfmXYIner")},
      {"yz_inertia_kg_m2", zero_default("PtfmYZIner")},
      {"xz_inertia_kg_m2", zero_default("PtfmXZIner")},
      {"reference_height_m", zero_default("PtfmRefzt: reference point above SWL")},
  });
  const Schema tower = Schema::map({
      {"base_height_m", any_number("TowerBsHt")},
      {"top_height_m", any_number("TowerHt")},
      {"station_fraction", Schema::sequence(Schema::number()).min_items(2).doc("HtFract, 0 … 1")},
      {"mass_density_kg_m", Schema::sequence(Schema::number()).min_items(2).doc("TMassDen at the stations")},
      {"mass_density_scale", Schema::number().at_least(0.0).default_value(1.0).doc("AdjTwMa")},
  });
  const Schema nacelle = Schema::map({
      {"mass_kg", non_negative("NacMass")},
      {"cm_m", number_vector(3, "NacCMxn, NacCMyn, NacCMzn from the tower top")},
      {"yaw_inertia_kg_m2", non_negative("NacYIner about the yaw axis")},
      {"yaw_bearing_mass_kg", Schema::number().at_least(0.0).default_value(0.0).doc("YawBrMass")},
      {"imu_m", number_vector(3, "NcIMUxn, NcIMUyn, NcIMUzn").optional()},
      {"tower_to_shaft_m", any_number("Twr2Shft")},
      {"overhang_m", any_number("OverHang (< 0 upwind)")},
      {"shaft_tilt_deg", any_number("ShftTilt (ElastoDyn sign)")},
      {"yaw_prescribed", Schema::boolean().default_value(false).doc("yaw prescribed (else fixed)")},
  });
  const Schema rotor = Schema::map({
      {"blade_count", Schema::integer().at_least(1).at_most(3).default_value(3).doc("NumBl")},
      {"hub_mass_kg", non_negative("HubMass")},
      {"hub_inertia_kg_m2", non_negative("HubIner about the shaft")},
      {"hub_cm_m", zero_default("HubCM")},
      {"hub_radius_m", non_negative("HubRad")},
      {"tip_radius_m", Schema::number().greater_than(0.0).doc("TipRad")},
      {"precone_deg", zero_default("PreCone (ElastoDyn sign)")},
      {"flexible_blades", Schema::boolean().default_value(false).doc("blades as flexible beams (root loads come in)")},
      {"blade_mass_kg", Schema::number().at_least(0.0).default_value(0.0).doc("one blade's mass (rigid)")},
      {"blade_first_mass_moment_kg_m", Schema::number().at_least(0.0).default_value(0.0).doc("about the root (rigid)")},
      {"blade_second_mass_moment_kg_m2", Schema::number().at_least(0.0).default_value(0.0).doc("about the root (rigid)")},
  });
  const Schema drivetrain = Schema::map({
      {"gearbox_ratio", Schema::number().greater_than(0.0).doc("GBRatio")},
      {"generator_inertia_kg_m2", non_negative("GenIner (HSS)")},
      {"torsional_flexibility", Schema::boolean().default_value(false).doc("DrTrDOF")},
      {"torsional_stiffness_N_m_rad", Schema::number().at_least(0.0).default_value(0.0).doc("DTTorSpr")},
      {"torsional_damping_N_m_s_rad", Schema::number().at_least(0.0).default_value(0.0).doc("DTTorDmp")},
  });
  const Schema initial = Schema::map({
      {"platform_position_m", number_vector(3, "PtfmSurge, PtfmSway, PtfmHeave").optional()},
      {"platform_angles_deg", number_vector(3, "PtfmRoll, PtfmPitch, PtfmYaw (Euler 1-2-3)").optional()},
      {"platform_velocity_m_s", number_vector(3, "reference-point velocity, inertial").optional()},
      {"platform_angular_velocity_deg_s", number_vector(3, "angular velocity, body frame").optional()},
      {"azimuth_deg", zero_default("Azimuth")},
      {"rotor_speed_rpm", zero_default("RotSpeed")},
      {"nacelle_yaw_deg", zero_default("NacYaw")},
      {"blade_pitch_deg", zero_default("BlPitch: initial pitch of every blade (held until the controller's first call)")},
  });
  auto free_dof = [](const char* doc) { return Schema::boolean().default_value(true).doc(doc); };
  const Schema dofs = Schema::map({
      {"surge", free_dof("PtfmSgDOF: false holds it at its initial value")},
      {"sway", free_dof("PtfmSwDOF")},
      {"heave", free_dof("PtfmHvDOF")},
      {"roll", free_dof("PtfmRDOF")},
      {"pitch", free_dof("PtfmPDOF")},
      {"yaw", free_dof("PtfmYDOF")},
      {"rotor_speed", Schema::choice({"free", "held"}).default_value("free")
                          .doc("GenDOF: held = the rotor turns at its initial speed")},
  });
  return Schema::map({
      {"degrees_of_freedom", dofs.optional().doc("DOF switches of the load case; absent = all free")},
      {"gravity_m_s2", Schema::number().at_least(0.0).default_value(9.80665).doc("gravity")},
      {"max_step_s", Schema::number().greater_than(0.0).default_value(0.02).doc("largest internal RK4 step")},
      {"platform", platform.doc("platform (rigid base body with the tower)")},
      {"tower", tower.doc("rigid tower, merged into the base body")},
      {"nacelle", nacelle.doc("nacelle on the yaw bearing")},
      {"rotor", rotor.doc("hub and rotor")},
      {"drivetrain", drivetrain.doc("drivetrain")},
      {"initial_conditions", initial.optional().doc("initial conditions; absent = at rest")},
  });
}

multibody::Params structure_params(const io::ValidatedDeck& d) {
  multibody::Params p;
  p.gravity_m_s2 = d.number("gravity_m_s2");
  p.max_step_s = d.number("max_step_s");
  const io::ValidatedDeck pl = d.section("platform");
  p.platform.mass_kg = pl.number("mass_kg");
  p.platform.cm_m = vec3(pl, "cm_m");
  p.platform.roll_inertia_kg_m2 = pl.number("roll_inertia_kg_m2");
  p.platform.pitch_inertia_kg_m2 = pl.number("pitch_inertia_kg_m2");
  p.platform.yaw_inertia_kg_m2 = pl.number("yaw_inertia_kg_m2");
  p.platform.xy_inertia_kg_m2 = pl.number("xy_inertia_kg_m2");
  p.platform.yz_inertia_kg_m2 = pl.number("yz_inertia_kg_m2");
  p.platform.xz_inertia_kg_m2 = pl.number("xz_inertia_kg_m2");
  p.platform.reference_height_m = pl.number("reference_height_m");
  const io::ValidatedDeck tw = d.section("tower");
  p.tower.base_height_m = tw.number("base_height_m");
  p.tower.top_height_m = tw.number("top_height_m");
  p.tower.station_fraction = tw.numbers("station_fraction");
  p.tower.mass_density_kg_m = tw.numbers("mass_density_kg_m");
  p.tower.mass_density_scale = tw.number("mass_density_scale");
  const io::ValidatedDeck na = d.section("nacelle");
  p.nacelle.mass_kg = na.number("mass_kg");
  p.nacelle.cm_m = vec3(na, "cm_m");
  p.nacelle.yaw_inertia_kg_m2 = na.number("yaw_inertia_kg_m2");
  p.nacelle.yaw_bearing_mass_kg = na.number("yaw_bearing_mass_kg");
  if (na.has("imu_m")) p.nacelle.imu_m = vec3(na, "imu_m");
  p.nacelle.tower_to_shaft_m = na.number("tower_to_shaft_m");
  p.nacelle.overhang_m = na.number("overhang_m");
  p.nacelle.shaft_tilt_deg = na.number("shaft_tilt_deg");
  p.nacelle.yaw_prescribed = na.boolean("yaw_prescribed");
  const io::ValidatedDeck ro = d.section("rotor");
  p.rotor.blade_count = static_cast<int>(ro.integer("blade_count"));
  p.rotor.hub_mass_kg = ro.number("hub_mass_kg");
  p.rotor.hub_inertia_kg_m2 = ro.number("hub_inertia_kg_m2");
  p.rotor.hub_cm_m = ro.number("hub_cm_m");
  p.rotor.hub_radius_m = ro.number("hub_radius_m");
  p.rotor.tip_radius_m = ro.number("tip_radius_m");
  p.rotor.precone_deg = ro.number("precone_deg");
  p.rotor.flexible_blades = ro.boolean("flexible_blades");
  p.rotor.blade_mass_kg = ro.number("blade_mass_kg");
  p.rotor.blade_first_mass_moment_kg_m = ro.number("blade_first_mass_moment_kg_m");
  p.rotor.blade_second_mass_moment_kg_m2 = ro.number("blade_second_mass_moment_kg_m2");
  const io::ValidatedDeck dt = d.section("drivetrain");
  p.drivetrain.gearbox_ratio = dt.number("gearbox_ratio");
  p.drivetrain.generator_inertia_kg_m2 = dt.number("generator_inertia_kg_m2");
  p.drivetrain.torsional_flexibility = dt.boolean("torsional_flexibility");
  p.drivetrain.torsional_stiffness_N_m_rad = dt.number("torsional_stiffness_N_m_rad");
  p.drivetrain.torsional_damping_N_m_s_rad = dt.number("torsional_damping_N_m_s_rad");
  if (d.has("degrees_of_freedom")) {
    const io::ValidatedDeck f = d.section("degrees_of_freedom");
    const char* names[] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};
    for (int i = 0; i < 6; ++i) p.dofs.platform_free[i] = f.boolean(names[i]);
    if (f.string("rotor_speed") == "held") p.dofs.rotor = multibody::RotorSpin::held;
  }
  if (d.has("initial_conditions")) {
    const io::ValidatedDeck ic = d.section("initial_conditions");
    auto v3 = [&](const char* key) { return ic.has(key) ? vec3(ic, key) : Vec3::Zero(); };
    p.initial_conditions.platform_position_m = v3("platform_position_m");
    p.initial_conditions.platform_angles_deg = v3("platform_angles_deg");
    p.initial_conditions.platform_velocity_m_s = v3("platform_velocity_m_s");
    p.initial_conditions.platform_angular_velocity_deg_s = v3("platform_angular_velocity_deg_s");
    p.initial_conditions.azimuth_deg = ic.number("azimuth_deg");
    p.initial_conditions.rotor_speed_rpm = ic.number("rotor_speed_rpm");
    p.initial_conditions.nacelle_yaw_deg = ic.number("nacelle_yaw_deg");
  }
  return p;
}

}  // namespace fowtsim::driver
