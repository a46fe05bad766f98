#include "decks/structure_deck.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "decks/deck_section.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/flexbody/blade_deck.hpp"

namespace fowtsim::driver {

using io::Schema;

namespace {

Schema non_negative(const char* doc) { return Schema::number().at_least(0.0).doc(doc); }
Schema any_number(const char* doc) { return Schema::number().doc(doc); }
Schema zero_default(const char* doc) { return Schema::number().default_value(0.0).doc(doc); }

// Initial conditions are checked for sense, so that a slip (1e19 for 1.9) stops at its line as an
// input error instead of failing the run at t = 0 in some module. The bounds are wide, each with
// its reason; tighter ones that need another key are checked in check_initial_conditions.
constexpr double kMaxOffsetM = 1000.0;        // beyond any mooring footprint (OC3's anchors lie 853.87 m out)
constexpr double kMaxHeaveM = 100.0;          // floating platforms heave metres; 100 m lifts most of a spar out
                                              // of the water (OC3: 120 m draft) or sinks a semi-submersible
constexpr double kMaxTiltDeg = 90.0;          // rolled or pitched by 90° a platform lies on its side (and
                                              // Euler 1-2-3 is singular at a pitch of 90°)
constexpr double kMaxSpeedM_s = 50.0;         // 5× a 50-year sea's orbital velocity at the surface
constexpr double kMaxRateDeg_s = 180.0;       // half a turn a second: 10× any platform's rate in storms
constexpr double kMaxRotorRpm = 100.0;        // multi-megawatt rotors turn at 5–20 rpm
constexpr double kSpeedOfSoundM_s = 343.0;    // a blade tip beyond it is no wind turbine (tips run at ≤ 100 m/s)

Schema bounded_vector(double bound, const char* doc) {
  return Schema::sequence(Schema::number().at_least(-bound).at_most(bound)).min_items(3).max_items(3).doc(doc);
}
Schema bounded(double low, double high, const char* doc) { return Schema::number().at_least(low).at_most(high).default_value(0.0).doc(doc); }

// Each key once: name, schema and the Params field it fills (decks/deck_section.hpp).
const DeckSection<multibody::Params>& structure_section() {
  using namespace multibody;
  static const DeckSection<Params> section = [] {
    DeckSection<PlatformParams> platform;
    platform.key("mass_kg", non_negative("PtfmMass"), &PlatformParams::mass_kg)
        .key("cm_m", number_vector(3, "platform CM from SWL, body frame (PtfmCMxt, PtfmCMyt, PtfmCMzt)"), &PlatformParams::cm_m)
        .key("roll_inertia_kg_m2", non_negative("PtfmRIner, about the CM"), &PlatformParams::roll_inertia_kg_m2)
        .key("pitch_inertia_kg_m2", non_negative("PtfmPIner, about the CM"), &PlatformParams::pitch_inertia_kg_m2)
        .key("yaw_inertia_kg_m2", non_negative("PtfmYIner, about the CM"), &PlatformParams::yaw_inertia_kg_m2)
        .key("xy_inertia_kg_m2", zero_default("PtfmXYIner"), &PlatformParams::xy_inertia_kg_m2)
        .key("yz_inertia_kg_m2", zero_default("PtfmYZIner"), &PlatformParams::yz_inertia_kg_m2)
        .key("xz_inertia_kg_m2", zero_default("PtfmXZIner"), &PlatformParams::xz_inertia_kg_m2)
        .key("reference_height_m", zero_default("PtfmRefzt: reference point above SWL"), &PlatformParams::reference_height_m);
    DeckSection<TowerParams> tower;
    tower.key("base_height_m", any_number("TowerBsHt"), &TowerParams::base_height_m)
        .key("top_height_m", any_number("TowerHt"), &TowerParams::top_height_m)
        .key("station_fraction", Schema::sequence(Schema::number()).min_items(2).doc("HtFract, 0 … 1"), &TowerParams::station_fraction)
        .key("mass_density_kg_m", Schema::sequence(Schema::number()).min_items(2).doc("TMassDen at the stations"),
             &TowerParams::mass_density_kg_m)
        .key("mass_density_scale", Schema::number().at_least(0.0).default_value(1.0).doc("AdjTwMa"), &TowerParams::mass_density_scale)
        .key("flexible", Schema::boolean().default_value(false).doc("TwFADOF/TwSSDOF: tower bending modes as DOFs (else rigid)"),
             &TowerParams::flexible)
        .key("fore_aft_stiffness_N_m2", Schema::sequence(Schema::number()).optional().doc("TwFAStif at the stations (flexible)"),
             &TowerParams::fore_aft_stiffness_N_m2)
        .key("side_side_stiffness_N_m2", Schema::sequence(Schema::number()).optional().doc("TwSSStif at the stations (flexible)"),
             &TowerParams::side_side_stiffness_N_m2)
        .key("fore_aft_mode_shapes", Schema::sequence(Schema::sequence(Schema::number()).min_items(5).max_items(5)).optional()
                                         .doc("TwFAM1Sh(2..6), TwFAM2Sh(2..6): one row of 5 per fore-aft mode (flexible)"),
             &TowerParams::fore_aft_mode_shapes)
        .key("side_side_mode_shapes", Schema::sequence(Schema::sequence(Schema::number()).min_items(5).max_items(5)).optional()
                                          .doc("TwSSM1Sh(2..6), TwSSM2Sh(2..6): one row of 5 per side-side mode (flexible)"),
             &TowerParams::side_side_mode_shapes)
        .key("fore_aft_damping_percent", Schema::sequence(Schema::number().at_least(0.0)).optional().doc("TwrFADmp per mode [%]"),
             &TowerParams::fore_aft_damping_percent)
        .key("side_side_damping_percent", Schema::sequence(Schema::number().at_least(0.0)).optional().doc("TwrSSDmp per mode [%]"),
             &TowerParams::side_side_damping_percent)
        .key("gauge_heights_m", Schema::sequence(Schema::number().at_least(0.0)).max_items(9).optional()
                                    .doc("NTwGages/TwrGagNd: tower gauges (TwHt1 … TwHt9 channels) as heights above the tower base "
                                         "[m], below the top; ElastoDyn's node J of TwrNodes is at (J − 0.5)(TowerHt − TowerBsHt)/TwrNodes"),
             &TowerParams::gauge_heights_m);
    DeckSection<NacelleParams> nacelle;
    nacelle.key("mass_kg", non_negative("NacMass"), &NacelleParams::mass_kg)
        .key("cm_m", number_vector(3, "NacCMxn, NacCMyn, NacCMzn from the tower top"), &NacelleParams::cm_m)
        .key("yaw_inertia_kg_m2", non_negative("NacYIner about the yaw axis"), &NacelleParams::yaw_inertia_kg_m2)
        .key("yaw_bearing_mass_kg", Schema::number().at_least(0.0).default_value(0.0).doc("YawBrMass"),
             &NacelleParams::yaw_bearing_mass_kg)
        .key("imu_m", number_vector(3, "NcIMUxn, NcIMUyn, NcIMUzn").optional(), &NacelleParams::imu_m)
        .key("tower_to_shaft_m", any_number("Twr2Shft"), &NacelleParams::tower_to_shaft_m)
        .key("overhang_m", any_number("OverHang (< 0 upwind)"), &NacelleParams::overhang_m)
        .key("shaft_tilt_deg", any_number("ShftTilt (ElastoDyn sign)"), &NacelleParams::shaft_tilt_deg)
        .key("yaw_prescribed", Schema::boolean().default_value(false).doc("yaw prescribed (else fixed)"), &NacelleParams::yaw_prescribed);
    DeckSection<RotorParams> rotor;
    rotor.key("blade_count", Schema::integer().at_least(1).at_most(3).default_value(3).doc("NumBl"), &RotorParams::blade_count)
        .key("hub_mass_kg", non_negative("HubMass"), &RotorParams::hub_mass_kg)
        .key("hub_inertia_kg_m2", non_negative("HubIner about the shaft"), &RotorParams::hub_inertia_kg_m2)
        .key("hub_cm_m", zero_default("HubCM"), &RotorParams::hub_cm_m)
        .key("hub_radius_m", non_negative("HubRad"), &RotorParams::hub_radius_m)
        .key("tip_radius_m", Schema::number().greater_than(0.0).doc("TipRad"), &RotorParams::tip_radius_m)
        .key("precone_deg", zero_default("PreCone (ElastoDyn sign)"), &RotorParams::precone_deg)
        .key("flexible_blades", Schema::boolean().default_value(false).doc("blades as flexible beams (root loads come in)"),
             &RotorParams::flexible_blades)
        .key("blade_mass_kg", Schema::number().at_least(0.0).default_value(0.0).doc("one blade's mass (rigid)"),
             &RotorParams::blade_mass_kg)
        .key("blade_first_mass_moment_kg_m", Schema::number().at_least(0.0).default_value(0.0).doc("about the root (rigid)"),
             &RotorParams::blade_first_mass_moment_kg_m)
        .key("blade_second_mass_moment_kg_m2", Schema::number().at_least(0.0).default_value(0.0).doc("about the root (rigid)"),
             &RotorParams::blade_second_mass_moment_kg_m2)
        .custom("rayleigh_ritz_blade_file",
                Schema::string().optional().doc("FlapDOF1/2, EdgeDOF: Rayleigh-Ritz blades from an ElastoDyn blade deck (e.g. "
                                                "inputs/nrel5mw/blade_elastodyn.yaml), relative to this deck file; absent = rigid"),
                [](const io::ValidatedDeck& d, const std::string& key, RotorParams& r) {
                  const std::filesystem::path file = file_beside_deck(d, key);  // names the deck line itself
                  try {
                    r.rayleigh_ritz_blade = flexbody::read_elastodyn_blade(file);
                  } catch (const InputError& e) {
                    throw InputError(e.context(), where(d, key) + ": " + e.message());
                  }
                })
        .key("rayleigh_ritz_blade_nodes", Schema::integer().at_least(1).at_most(1000).default_value(17).doc("BldNodes: the Rayleigh-Ritz blades' "
                                                                                               "integration nodes (ElastoDyn's midpoint rule)"),
             &RotorParams::rayleigh_ritz_blade_nodes)
        .key("rayleigh_ritz_blade_gauges", Schema::sequence(Schema::number().at_least(0.0).less_than(1.0)).max_items(9).optional()
                                               .doc("NBlGages/BldGagNd: span fractions x/L from the root for the Spn<k>FL/ML{x,y,z}b<b> "
                                                    "channels (Rayleigh-Ritz blades)"),
             &RotorParams::blade_gauge_fractions);
    DeckSection<DrivetrainParams> drivetrain;
    drivetrain.key("gearbox_ratio", Schema::number().greater_than(0.0).doc("GBRatio"), &DrivetrainParams::gearbox_ratio)
        .key("generator_inertia_kg_m2", non_negative("GenIner (HSS)"), &DrivetrainParams::generator_inertia_kg_m2)
        .key("torsional_flexibility", Schema::boolean().default_value(false).doc("DrTrDOF"), &DrivetrainParams::torsional_flexibility)
        .key("torsional_stiffness_N_m_rad", Schema::number().at_least(0.0).default_value(0.0).doc("DTTorSpr"),
             &DrivetrainParams::torsional_stiffness_N_m_rad)
        .key("torsional_damping_N_m_s_rad", Schema::number().at_least(0.0).default_value(0.0).doc("DTTorDmp"),
             &DrivetrainParams::torsional_damping_N_m_s_rad);
    DeckSection<InitialConditions> initial;
    initial.key("platform_position_m", bounded_vector(kMaxOffsetM, "PtfmSurge, PtfmSway, PtfmHeave; each within ±1000 m (beyond "
                                                                   "any mooring footprint), the heave within ±100 m").optional(),
                &InitialConditions::platform_position_m)
        .key("platform_angles_deg", bounded_vector(180.0, "PtfmRoll, PtfmPitch, PtfmYaw (Euler 1-2-3); roll and pitch within "
                                                          "±90° (beyond, the platform lies on its side)").optional(),
             &InitialConditions::platform_angles_deg)
        .key("platform_velocity_m_s", bounded_vector(kMaxSpeedM_s, "reference-point velocity, inertial (±50 m/s: 5× a "
                                                                   "50-year sea's orbital velocity)").optional(),
             &InitialConditions::platform_velocity_m_s)
        .key("platform_angular_velocity_deg_s", bounded_vector(kMaxRateDeg_s, "angular velocity, body frame (±180°/s: 10× "
                                                                              "any platform's rate in storms)").optional(),
             &InitialConditions::platform_angular_velocity_deg_s)
        .key("azimuth_deg", bounded(-360.0, 360.0, "Azimuth (one turn either way: it wraps)"), &InitialConditions::azimuth_deg)
        .key("rotor_speed_rpm", bounded(-kMaxRotorRpm, kMaxRotorRpm, "RotSpeed (multi-megawatt rotors turn at 5–20 rpm; "
                                                                     "the blade tip must stay below the speed of sound)"),
             &InitialConditions::rotor_speed_rpm)
        .key("nacelle_yaw_deg", bounded(-180.0, 180.0, "NacYaw (half a turn either way)"), &InitialConditions::nacelle_yaw_deg)
        .key("tower_top_deflection_m", Schema::sequence(Schema::number().at_least(-20.0).at_most(20.0)).min_items(2).max_items(2)
                                           .optional().doc("TTDspFA, TTDspSS (flexible tower; on the 1st mode of each "
                                                           "direction; ±20 m: a quarter of a tower's height)"),
             &InitialConditions::tower_top_deflection_m)
        .key("blade_deflection", Schema::choice({"undeflected", "static"}).default_value("undeflected")
                                     .doc("Rayleigh-Ritz blades: undeflected (ElastoDyn's OoPDefl = IPDefl = 0) or their static "
                                          "deflection under gravity, the aerodynamic loads and the spin of the initial state "
                                          "(a sweep's trim sets static); MBBT blades start as blades.start says, rigid blades "
                                          "ignore it"),
             &InitialConditions::rayleigh_ritz_blades_static, [](const std::string& v) { return v == "static"; })
        .key("blade_pitch_deg", bounded(-90.0, 90.0, "BlPitch: initial pitch of every blade, held until the controller's "
                                                     "first call (90° is feathered; beyond, the blade faces backwards)"),
             &InitialConditions::blade_pitch_deg);
    auto free_dof = [](const char* doc) { return Schema::boolean().default_value(true).doc(doc); };
    auto platform_dof = [](int i) { return [i](DofSwitches& f) -> bool& { return f.platform_free[i]; }; };
    DeckSection<DofSwitches> dofs;
    dofs.key("surge", free_dof("PtfmSgDOF: false holds it at its initial value"), platform_dof(0))
        .key("sway", free_dof("PtfmSwDOF"), platform_dof(1))
        .key("heave", free_dof("PtfmHvDOF"), platform_dof(2))
        .key("roll", free_dof("PtfmRDOF"), platform_dof(3))
        .key("pitch", free_dof("PtfmPDOF"), platform_dof(4))
        .key("yaw", free_dof("PtfmYDOF"), platform_dof(5))
        .key("rotor_speed", Schema::choice({"free", "held"}).default_value("free").doc("GenDOF: held = the rotor turns at its initial speed"),
             &DofSwitches::rotor, [](const std::string& v) { return v == "held" ? RotorSpin::held : RotorSpin::free; });
    DeckSection<Params> s;
    s.section("degrees_of_freedom", dofs, &Params::dofs, true, "DOF switches of the load case; absent = all free")
        .key("gravity_m_s2", Schema::number().at_least(0.0).default_value(9.80665).doc("gravity"), &Params::gravity_m_s2)
        .key("max_step_s", Schema::number().greater_than(0.0).default_value(0.02).doc("largest internal RK4 step [s] (with MBBT blades on the flexible tower: at least simulation.dt_s, one step per large step)"), &Params::max_step_s)
        .section("platform", platform, &Params::platform, false, "platform (rigid base body with the tower)")
        .section("tower", tower, &Params::tower, false, "rigid tower, merged into the base body")
        .section("nacelle", nacelle, &Params::nacelle, false, "nacelle on the yaw bearing")
        .section("rotor", rotor, &Params::rotor, false, "hub and rotor")
        .section("drivetrain", drivetrain, &Params::drivetrain, false, "drivetrain")
        .section("initial_conditions", initial, &Params::initial_conditions, true, "initial conditions; absent = at rest");
    return s;
  }();
  return section;
}

// The bounds of one component of a vector key, or of two keys together, that the schema cannot say.
void check_initial_conditions(const io::ValidatedDeck& d, const multibody::Params& p) {
  const multibody::InitialConditions& ic = p.initial_conditions;
  const auto refuse = [&](const std::string& key, const std::string& message) {
    throw InputError({"structure", std::nullopt, key, ""}, where(d, key) + ": " + message);
  };
  if (std::abs(ic.platform_position_m.z()) > kMaxHeaveM)
    refuse("initial_conditions.platform_position_m",
           fmt::format("heave {:g} m: expected within ±{:g} m (a platform heaves metres; 100 m lifts a spar mostly out of the "
                       "water or sinks a semi-submersible)",
                       ic.platform_position_m.z(), kMaxHeaveM));
  for (int k : {0, 1})
    if (!(std::abs(ic.platform_angles_deg[k]) < kMaxTiltDeg))
      refuse("initial_conditions.platform_angles_deg",
             fmt::format("{} {:g}°: expected within ±{:g}° (beyond, the platform lies on its side; Euler 1-2-3 is singular at a "
                         "pitch of 90°)",
                         k == 0 ? "roll" : "pitch", ic.platform_angles_deg[k], kMaxTiltDeg));
  const double tip_speed_m_s = std::abs(ic.rotor_speed_rpm) * 2.0 * std::numbers::pi / 60.0 * p.rotor.tip_radius_m;
  if (tip_speed_m_s >= kSpeedOfSoundM_s)
    refuse("initial_conditions.rotor_speed_rpm",
           fmt::format("{:g} rpm turns the {:g}-m blade tip at {:.0f} m/s: expected below the speed of sound ({:g} m/s; wind "
                       "turbine tips run at ≤ 100 m/s)",
                       ic.rotor_speed_rpm, p.rotor.tip_radius_m, tip_speed_m_s, kSpeedOfSoundM_s));
}

}  // namespace

Schema structure_schema() { return structure_section().schema(); }

multibody::Params structure_params(const io::ValidatedDeck& d) {
  multibody::Params p = structure_section().read(d);
  check_initial_conditions(d, p);
  return p;
}

}  // namespace fowtsim::driver
