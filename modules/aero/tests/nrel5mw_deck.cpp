#include "nrel5mw_deck.hpp"

#include <map>
#include <numbers>
#include <stdexcept>
#include <string>

#include <yaml-cpp/yaml.h>

#include "fowtsim/testing/skip.hpp"

namespace fowtsim::aero::testing {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

template <class E>
E choose(const YAML::Node& node, const std::map<std::string, E>& names) {
  const auto it = names.find(node.as<std::string>());
  if (it == names.end()) throw std::runtime_error("unknown option " + node.as<std::string>());
  return it->second;
}

}  // namespace

Params load_aero_deck(const std::filesystem::path& aero_yaml) {
  const YAML::Node root = YAML::LoadFile(aero_yaml.string());
  const YAML::Node a = root["aero"];
  const PolarInterpolation interpolation = choose<PolarInterpolation>(
      a["polar_interpolation"], {{"linear", PolarInterpolation::linear},
                                 {"cubic_spline", PolarInterpolation::cubic_spline}});
  Params p;
  std::map<std::string, int> airfoil_index;
  for (const YAML::Node& inc : root["include"]) {
    const YAML::Node airfoils = YAML::LoadFile((aero_yaml.parent_path() / inc.as<std::string>()).string());
    for (const YAML::Node& af : airfoils["airfoils"]) {
      std::vector<double> alpha, cl, cd, cm;
      for (const YAML::Node& row : af["polar"]) {
        alpha.push_back(row[0].as<double>());
        cl.push_back(row[1].as<double>());
        cd.push_back(row[2].as<double>());
        cm.push_back(row[3].as<double>());
      }
      const std::string name = af["name"].as<std::string>();
      airfoil_index[name] = static_cast<int>(p.airfoils.size());
      p.airfoils.emplace_back(name, alpha, cl, cd, cm, interpolation);
    }
  }
  p.air_density_kg_m3 = a["air_density_kg_m3"].as<double>();
  p.number_of_blades = a["number_of_blades"].as<int>();
  p.tip_loss = a["tip_loss"].as<bool>();
  p.hub_loss = a["hub_loss"].as<bool>();
  p.tangential_induction = a["tangential_induction"].as<bool>();
  p.drag_in_axial_induction = a["drag_in_axial_induction"].as<bool>();
  p.drag_in_tangential_induction = a["drag_in_tangential_induction"].as<bool>();
  p.high_induction_correction = choose<HighInductionCorrection>(
      a["high_induction_correction"], {{"none", HighInductionCorrection::none}, {"buhl", HighInductionCorrection::buhl}});
  p.skew_model = choose<SkewModel>(a["skew_model"], {{"none", SkewModel::none}, {"pitt_peters", SkewModel::pitt_peters}});
  p.skew_factor = a["skew_factor"].as<double>();
  p.pitching_moment = a["pitching_moment"].as<bool>();
  p.tower_potential = choose<TowerPotential>(
      a["tower_potential"], {{"none", TowerPotential::none}, {"baseline", TowerPotential::baseline}, {"bak", TowerPotential::bak}});
  p.tower_shadow = choose<TowerShadow>(
      a["tower_shadow"], {{"none", TowerShadow::none}, {"powles", TowerShadow::powles}, {"eames", TowerShadow::eames}});
  p.output_nodes = a["output_nodes"].as<std::vector<int>>();
  for (const YAML::Node& row : a["blade"]["nodes"]) {
    BladeNodeParams n;
    n.span_m = row[0].as<double>();
    n.curve_ac_m = row[1].as<double>();
    n.sweep_ac_m = row[2].as<double>();
    n.curve_angle_rad = row[3].as<double>() * kDegree;
    n.twist_rad = row[4].as<double>() * kDegree;
    n.chord_m = row[5].as<double>();
    n.airfoil = airfoil_index.at(row[6].as<std::string>());
    p.blade.push_back(n);
  }
  for (const YAML::Node& row : a["tower"]["nodes"]) {
    p.tower.push_back({row[0].as<double>(), row[1].as<double>(), row[2].as<double>(), row[3].as<double>()});
  }
  validate(p);
  return p;
}

Params load_nrel5mw_deck() {
  return load_aero_deck(fowtsim::testing::source_dir() / "inputs" / "nrel5mw" / "aero.yaml");
}

}  // namespace fowtsim::aero::testing
