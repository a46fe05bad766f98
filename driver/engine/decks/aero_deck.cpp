#include "decks/aero_deck.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "decks/deck_section.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

using io::Schema;

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

double number_at(const io::ValidatedDeck& d, const std::string& path) {
  const std::string text = d.string(path);
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size() && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  throw InputError({"aero", std::nullopt, path, "a number"}, where(d, path) + ": expected a number, found '" + text + "'");
}

// One entry of the `airfoils` section as written; its Polar is built with the aero section's
// polar_interpolation.
struct AirfoilKeys {
  std::string name;
  std::vector<std::array<double, 4>> polar;  // alpha_deg, cl, cd, cm
};

// aero::Params and the aero keys that fill no Params field as written: the interpolation the
// polars are built with, the blade rows (their airfoil names index the airfoils section) and the
// tower stations. add_blade_and_tower turns them into Params fields after the polars are built.
struct AeroKeys : aero::Params {
  aero::PolarInterpolation polar_interpolation = aero::PolarInterpolation::cubic_spline;
  std::vector<std::vector<std::string>> blade_rows;
  std::vector<std::array<double, 4>> tower_nodes;
};

// Each key once: name, schema and the field it fills (decks/deck_section.hpp).
const DeckSection<AirfoilKeys>& airfoil_section() {
  static const DeckSection<AirfoilKeys> section = [] {
    DeckSection<AirfoilKeys> af;
    af.key("name", Schema::string().doc("airfoil name, referenced by the blade rows"), &AirfoilKeys::name)
        .key("polar", Schema::sequence(number_vector(4, "alpha_deg, cl, cd, cm")).min_items(2)
                          .doc("static polar over ±180°, alpha ascending"),
             &AirfoilKeys::polar);
    return af;
  }();
  return section;
}

const DeckSection<AeroKeys>& aero_section() {
  using namespace aero;
  static const DeckSection<AeroKeys> section = [] {
    // blade and tower are mappings of one key, `nodes`, read into AeroKeys itself.
    const auto same = [](AeroKeys& k) -> AeroKeys& { return k; };
    DeckSection<AeroKeys> blade;
    blade.key("nodes", Schema::sequence(Schema::sequence(Schema::string()).min_items(7).max_items(7)
                                            .doc("span_m, curve_ac_m, sweep_ac_m, curve_angle_deg, twist_deg, chord_m, airfoil name"))
                           .min_items(2).doc("root to tip"),
              &AeroKeys::blade_rows);
    DeckSection<AeroKeys> tower;
    tower.key("nodes", Schema::sequence(number_vector(4, "elevation_m, diameter_m, cd, ti")).min_items(2).doc("tower stations"),
              &AeroKeys::tower_nodes);
    DeckSection<AeroKeys> a;
    a.key("air_density_kg_m3", Schema::number().greater_than(0.0).default_value(1.225).doc("air density"),
          &Params::air_density_kg_m3)
        .key("number_of_blades", Schema::integer().at_least(1).at_most(10).default_value(3).doc("blades"), &Params::number_of_blades)
        .key("polar_interpolation", Schema::choice({"linear", "cubic_spline"}).default_value("cubic_spline").doc("polar lookup in α"),
             &AeroKeys::polar_interpolation,
             [](const std::string& v) { return v == "linear" ? PolarInterpolation::linear : PolarInterpolation::cubic_spline; })
        .key("tip_loss", Schema::boolean().default_value(true).doc("Prandtl tip loss"), &Params::tip_loss)
        .key("hub_loss", Schema::boolean().default_value(true).doc("Prandtl hub loss"), &Params::hub_loss)
        .key("tangential_induction", Schema::boolean().default_value(true).doc("solve for a'"), &Params::tangential_induction)
        .key("drag_in_axial_induction", Schema::boolean().default_value(false).doc("Cd in the axial induction"),
             &Params::drag_in_axial_induction)
        .key("drag_in_tangential_induction", Schema::boolean().default_value(false).doc("Cd in the tangential induction"),
             &Params::drag_in_tangential_induction)
        .key("high_induction_correction", Schema::choice({"buhl", "none"}).default_value("buhl").doc("high-induction correction"),
             &Params::high_induction_correction,
             [](const std::string& v) { return v == "buhl" ? HighInductionCorrection::buhl : HighInductionCorrection::none; })
        .key("skew_model", Schema::choice({"pitt_peters", "none"}).default_value("pitt_peters").doc("skewed-wake redistribution"),
             &Params::skew_model, [](const std::string& v) { return v == "pitt_peters" ? SkewModel::pitt_peters : SkewModel::none; })
        .key("skew_factor", Schema::number().at_least(0.0).default_value(15.0 * std::numbers::pi / 32.0).doc("redistribution factor K"),
             &Params::skew_factor)
        .key("pitching_moment", Schema::boolean().default_value(true).doc("apply Cm"), &Params::pitching_moment)
        .key("unsteady_airfoil", Schema::choice({"none", "hgm"}).default_value("none")
                                     .doc("unsteady airfoil aerodynamics: none = static polar; hgm = Hansen-Gaunaa-Madsen "
                                          "4-state dynamic stall (AeroDyn UA_Mod 4), alpha0/slope/f from the polars"),
             &Params::unsteady_airfoil,
             [](const std::string& v) { return v == "hgm" ? UnsteadyAirfoilModel::hgm : UnsteadyAirfoilModel::none; })
        .key("ua_pressure_time_constant", Schema::number().greater_than(0.0).default_value(1.5)
                                              .doc("hgm: pressure-lag time constant tau_p in c/(2W) (HGM 1.5; AeroDyn T_p0 1.7)"),
             &Params::ua_pressure_time_constant)
        .key("ua_separation_time_constant", Schema::number().greater_than(0.0).default_value(6.0)
                                                .doc("hgm: separation time constant tau_f in c/(2W) (HGM 6.0; AeroDyn T_f0 3)"),
             &Params::ua_separation_time_constant)
        .key("ua_cutout_deg", Schema::number().at_least(5.0).at_most(90.0).default_value(45.0)
                                  .doc("hgm: static polar beyond |alpha| (blended over the 5 deg below; AeroDyn UACutout)"),
             &Params::ua_cutout_rad, [](double deg) { return kDegree * deg; })
        .key("dynamic_inflow", Schema::choice({"none", "oye"}).default_value("none")
                                   .doc("dynamic inflow: none = quasi-steady BEM induction; oye = Oye two-filter DBEMT "
                                        "(AeroDyn DBEMT_Mod 2, tau1 = 1.1/(1-1.3 min(a,0.5)) R/U, k = 0.6)"),
             &Params::dynamic_inflow, [](const std::string& v) { return v == "oye" ? DynamicInflowModel::oye : DynamicInflowModel::none; })
        .key("induction", Schema::choice({"stage", "step"}).default_value("stage")
                              .doc("rigid and Rayleigh-Ritz blades: BEM inductions solved at every RK4 stage (stage), or at each "
                                   "large step's start and held over its stages (step: about 30 % faster on the OC3 load case, "
                                   "its statistics within 0.1 %)"),
             &Params::induction_held_over_step, [](const std::string& v) { return v == "step"; })
        .key("tower_potential", Schema::choice({"none", "baseline", "bak"}).default_value("none").doc("tower potential flow"),
             &Params::tower_potential,
             [](const std::string& v) {
               return v == "baseline" ? TowerPotential::baseline : v == "bak" ? TowerPotential::bak : TowerPotential::none;
             })
        .key("tower_shadow", Schema::choice({"none", "powles", "eames"}).default_value("none").doc("tower wake deficit"),
             &Params::tower_shadow,
             [](const std::string& v) {
               return v == "powles" ? TowerShadow::powles : v == "eames" ? TowerShadow::eames : TowerShadow::none;
             })
        .key("tower_drag", Schema::boolean().default_value(false)
                               .doc("aerodynamic drag on the tower, 1/2 rho Cd D |v|v normal to its axis (AeroDyn TwrAero)"),
             &Params::tower_drag)
        .key("output_nodes", Schema::sequence(Schema::integer().at_least(1)).max_items(9).optional().doc("1-based nodes of B·N· channels"),
             &Params::output_nodes)
        .section("blade", blade, same, false, "blade aerodynamic geometry")
        .section("tower", tower, same, true, "tower for its influence on the inflow and its drag");
    return a;
  }();
  return section;
}

// The blade nodes from their rows (numbers written as strings beside the airfoil name, read here
// with file:line on a bad entry; the name indexes `names`), and the tower stations.
void add_blade_and_tower(const io::ValidatedDeck& a, const AeroKeys& keys, const std::vector<std::string>& names,
                         aero::Params& p) {
  for (std::size_t i = 0; i < keys.blade_rows.size(); ++i) {
    const std::string row = fmt::format("blade.nodes[{}]", i);
    aero::BladeNodeParams n;
    n.span_m = number_at(a, row + "[0]");
    n.curve_ac_m = number_at(a, row + "[1]");
    n.sweep_ac_m = number_at(a, row + "[2]");
    n.curve_angle_rad = kDegree * number_at(a, row + "[3]");
    n.twist_rad = kDegree * number_at(a, row + "[4]");
    n.chord_m = number_at(a, row + "[5]");
    const std::string& airfoil = keys.blade_rows[i][6];
    const auto it = std::find(names.begin(), names.end(), airfoil);
    if (it == names.end())
      throw InputError({"aero", std::nullopt, row, "an airfoil listed under airfoils"},
                       where(a, row + "[6]") + ": unknown airfoil '" + airfoil + "'");
    n.airfoil = static_cast<int>(it - names.begin());
    p.blade.push_back(n);
  }
  for (const std::array<double, 4>& v : keys.tower_nodes) p.tower.push_back({v[0], v[1], v[2], v[3]});
}

}  // namespace

Schema airfoils_schema() { return Schema::sequence(airfoil_section().schema()).min_items(1); }

Schema aero_schema() { return aero_section().schema(); }

aero::Params aero_params(const io::ValidatedDeck& deck) {
  const io::ValidatedDeck a = deck.section("aero");
  AeroKeys keys;
  aero_section().read_into(a, keys);
  aero::Params p = keys;  // the Params fields; the other keys become fields below
  // The polars are built (and checked) before the blade rows are read, so that a deck with errors
  // in both reports the polar first.
  std::vector<std::string> names;
  for (std::size_t i = 0; i < deck.size("airfoils"); ++i) {
    const io::ValidatedDeck af = deck.section(fmt::format("airfoils[{}]", i));
    AirfoilKeys airfoil;
    airfoil_section().read_into(af, airfoil);
    std::vector<double> alpha, cl, cd, cm;
    for (const std::array<double, 4>& row : airfoil.polar) {
      alpha.push_back(row[0]);
      cl.push_back(row[1]);
      cd.push_back(row[2]);
      cm.push_back(row[3]);
    }
    names.push_back(airfoil.name);
    located(af, [&] { p.airfoils.emplace_back(names.back(), alpha, cl, cd, cm, keys.polar_interpolation); });
  }
  add_blade_and_tower(a, keys, names, p);
  located(a, [&] { aero::validate(p); });
  return p;
}

}  // namespace fowtsim::driver
