#include "decks/aero_deck.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
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

}  // namespace

Schema airfoils_schema() {
  const Schema airfoil = Schema::map({
      {"name", Schema::string().doc("airfoil name, referenced by the blade rows")},
      {"polar", Schema::sequence(number_vector(4, "alpha_deg, cl, cd, cm")).min_items(2)
                    .doc("static polar over ±180°, alpha ascending")},
  });
  return Schema::sequence(airfoil).min_items(1);
}

Schema aero_schema() {
  const Schema row7 = Schema::sequence(Schema::string()).min_items(7).max_items(7)
                          .doc("span_m, curve_ac_m, sweep_ac_m, curve_angle_deg, twist_deg, chord_m, airfoil name");
  return Schema::map({
      {"air_density_kg_m3", Schema::number().greater_than(0.0).default_value(1.225).doc("air density")},
      {"number_of_blades", Schema::integer().at_least(1).at_most(10).default_value(3).doc("blades")},
      {"polar_interpolation", Schema::choice({"linear", "cubic_spline"}).default_value("cubic_spline").doc("polar lookup in α")},
      {"tip_loss", Schema::boolean().default_value(true).doc("Prandtl tip loss")},
      {"hub_loss", Schema::boolean().default_value(true).doc("Prandtl hub loss")},
      {"tangential_induction", Schema::boolean().default_value(true).doc("solve for a'")},
      {"drag_in_axial_induction", Schema::boolean().default_value(false).doc("Cd in the axial induction")},
      {"drag_in_tangential_induction", Schema::boolean().default_value(false).doc("Cd in the tangential induction")},
      {"high_induction_correction", Schema::choice({"buhl", "none"}).default_value("buhl").doc("high-induction correction")},
      {"skew_model", Schema::choice({"pitt_peters", "none"}).default_value("pitt_peters").doc("skewed-wake redistribution")},
      {"skew_factor", Schema::number().at_least(0.0).default_value(15.0 * std::numbers::pi / 32.0).doc("redistribution factor K")},
      {"pitching_moment", Schema::boolean().default_value(true).doc("apply Cm")},
      {"unsteady_airfoil", Schema::choice({"none", "hgm"}).default_value("none")
                               .doc("unsteady airfoil aerodynamics: none = static polar; hgm = Hansen-Gaunaa-Madsen "
                                    "4-state dynamic stall (AeroDyn UA_Mod 4), alpha0/slope/f from the polars")},
      {"ua_pressure_time_constant", Schema::number().greater_than(0.0).default_value(1.5)
                                        .doc("hgm: pressure-lag time constant tau_p in c/(2W) (HGM 1.5; AeroDyn T_p0 1.7)")},
      {"ua_separation_time_constant", Schema::number().greater_than(0.0).default_value(6.0)
                                          .doc("hgm: separation time constant tau_f in c/(2W) (HGM 6.0; AeroDyn T_f0 3)")},
      {"ua_cutout_deg", Schema::number().at_least(5.0).at_most(90.0).default_value(45.0)
                            .doc("hgm: static polar beyond |alpha| (blended over the 5 deg below; AeroDyn UACutout)")},
      {"dynamic_inflow", Schema::choice({"none", "oye"}).default_value("none")
                             .doc("dynamic inflow: none = quasi-steady BEM induction; oye = Oye two-filter DBEMT "
                                  "(AeroDyn DBEMT_Mod 2, tau1 = 1.1/(1-1.3 min(a,0.5)) R/U, k = 0.6)")},
      {"tower_potential", Schema::choice({"none", "baseline", "bak"}).default_value("none").doc("tower potential flow")},
      {"tower_shadow", Schema::choice({"none", "powles", "eames"}).default_value("none").doc("tower wake deficit")},
      {"output_nodes", Schema::sequence(Schema::integer().at_least(1)).max_items(9).optional().doc("1-based nodes of B·N· channels")},
      {"blade", Schema::map({{"nodes", Schema::sequence(row7).min_items(2).doc("root to tip")}}).doc("blade aerodynamic geometry")},
      {"tower", Schema::map({{"nodes", Schema::sequence(number_vector(4, "elevation_m, diameter_m, cd, ti")).min_items(2)
                                           .doc("tower stations")}}).optional().doc("tower for its influence on the inflow")},
  });
}

aero::Params aero_params(const io::ValidatedDeck& deck) {
  const io::ValidatedDeck a = deck.section("aero");
  aero::Params p;
  p.air_density_kg_m3 = a.number("air_density_kg_m3");
  p.number_of_blades = static_cast<int>(a.integer("number_of_blades"));
  const aero::PolarInterpolation interpolation =
      a.string("polar_interpolation") == "linear" ? aero::PolarInterpolation::linear : aero::PolarInterpolation::cubic_spline;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < deck.size("airfoils"); ++i) {
    const io::ValidatedDeck af = deck.section(fmt::format("airfoils[{}]", i));
    std::vector<double> alpha, cl, cd, cm;
    for (std::size_t k = 0; k < af.size("polar"); ++k) {
      const std::vector<double> row = af.numbers(fmt::format("polar[{}]", k));
      alpha.push_back(row[0]);
      cl.push_back(row[1]);
      cd.push_back(row[2]);
      cm.push_back(row[3]);
    }
    names.push_back(af.string("name"));
    located(af, [&] { p.airfoils.emplace_back(names.back(), alpha, cl, cd, cm, interpolation); });
  }
  p.tip_loss = a.boolean("tip_loss");
  p.hub_loss = a.boolean("hub_loss");
  p.tangential_induction = a.boolean("tangential_induction");
  p.drag_in_axial_induction = a.boolean("drag_in_axial_induction");
  p.drag_in_tangential_induction = a.boolean("drag_in_tangential_induction");
  p.high_induction_correction =
      a.string("high_induction_correction") == "buhl" ? aero::HighInductionCorrection::buhl : aero::HighInductionCorrection::none;
  p.skew_model = a.string("skew_model") == "pitt_peters" ? aero::SkewModel::pitt_peters : aero::SkewModel::none;
  p.skew_factor = a.number("skew_factor");
  p.pitching_moment = a.boolean("pitching_moment");
  p.unsteady_airfoil = a.string("unsteady_airfoil") == "hgm" ? aero::UnsteadyAirfoilModel::hgm : aero::UnsteadyAirfoilModel::none;
  p.ua_pressure_time_constant = a.number("ua_pressure_time_constant");
  p.ua_separation_time_constant = a.number("ua_separation_time_constant");
  p.ua_cutout_rad = kDegree * a.number("ua_cutout_deg");
  p.dynamic_inflow = a.string("dynamic_inflow") == "oye" ? aero::DynamicInflowModel::oye : aero::DynamicInflowModel::none;
  const std::string potential = a.string("tower_potential"), shadow = a.string("tower_shadow");
  p.tower_potential = potential == "baseline" ? aero::TowerPotential::baseline
                      : potential == "bak"    ? aero::TowerPotential::bak
                                              : aero::TowerPotential::none;
  p.tower_shadow = shadow == "powles" ? aero::TowerShadow::powles : shadow == "eames" ? aero::TowerShadow::eames : aero::TowerShadow::none;
  for (std::size_t i = 0; i < a.size("blade.nodes"); ++i) {
    const std::string row = fmt::format("blade.nodes[{}]", i);
    aero::BladeNodeParams n;
    n.span_m = number_at(a, row + "[0]");
    n.curve_ac_m = number_at(a, row + "[1]");
    n.sweep_ac_m = number_at(a, row + "[2]");
    n.curve_angle_rad = kDegree * number_at(a, row + "[3]");
    n.twist_rad = kDegree * number_at(a, row + "[4]");
    n.chord_m = number_at(a, row + "[5]");
    const std::string airfoil = a.string(row + "[6]");
    const auto it = std::find(names.begin(), names.end(), airfoil);
    if (it == names.end())
      throw InputError({"aero", std::nullopt, row, "an airfoil listed under airfoils"},
                       where(a, row + "[6]") + ": unknown airfoil '" + airfoil + "'");
    n.airfoil = static_cast<int>(it - names.begin());
    p.blade.push_back(n);
  }
  if (a.has("tower")) {
    for (std::size_t i = 0; i < a.size("tower.nodes"); ++i) {
      const std::vector<double> v = a.numbers(fmt::format("tower.nodes[{}]", i));
      p.tower.push_back({v[0], v[1], v[2], v[3]});
    }
  }
  if (a.has("output_nodes"))
    for (std::size_t i = 0; i < a.size("output_nodes"); ++i) p.output_nodes.push_back(static_cast<int>(a.integer(fmt::format("output_nodes[{}]", i))));
  located(a, [&] { aero::validate(p); });
  return p;
}

}  // namespace fowtsim::driver
