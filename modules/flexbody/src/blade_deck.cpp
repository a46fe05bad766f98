#include "fowtsim/flexbody/blade_deck.hpp"

#include "fowtsim/core/error.hpp"

#include <yaml-cpp/yaml.h>

#include <string>

namespace fowtsim::flexbody {
namespace {

class Reader {
 public:
  explicit Reader(const std::filesystem::path& file) : file_(file.string()) {
    try {
      node_ = YAML::LoadFile(file_)["elastodyn_blade"];
    } catch (const YAML::Exception& e) {
      fail("(file)", e.what());
    }
    if (!node_) fail("elastodyn_blade", "section missing");
  }

  template <class T>
  T get(const char* key) const {
    const YAML::Node n = node_[key];
    if (!n) fail(key, "missing");
    try {
      return n.as<T>();
    } catch (const YAML::Exception& e) {
      fail(key, e.what());
    }
  }

  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw InputError({"flexbody.blade_deck", std::nullopt, key, "see inputs/nrel5mw/blade_elastodyn.yaml"},
                     file_ + ": elastodyn_blade." + key + ": " + message);
  }

 private:
  std::string file_;
  YAML::Node node_;
};

}  // namespace

ElastoDynBlade read_elastodyn_blade(const std::filesystem::path& file) {
  const Reader r(file);
  ElastoDynBlade b;
  b.hub_radius = r.get<double>("hub_radius_m");
  b.tip_radius = r.get<double>("tip_radius_m");
  b.flap_damping_percent = r.get<std::array<double, 2>>("flap_damping_percent");
  b.edge_damping_percent = r.get<double>("edge_damping_percent");
  b.flap_stiffness_tuners = r.get<std::array<double, 2>>("flap_stiffness_tuners");
  b.mass_factor = r.get<double>("mass_factor");
  b.flap_stiffness_factor = r.get<double>("flap_stiffness_factor");
  b.edge_stiffness_factor = r.get<double>("edge_stiffness_factor");
  b.flap1_shape = r.get<std::array<double, 5>>("flap1_shape");
  b.flap2_shape = r.get<std::array<double, 5>>("flap2_shape");
  b.edge1_shape = r.get<std::array<double, 5>>("edge1_shape");
  for (const auto& row : r.get<std::vector<std::array<double, 5>>>("stations")) {
    b.span_fraction.push_back(row[0]);
    b.twist_deg.push_back(row[1]);
    b.mass_density.push_back(row[2]);
    b.flap_stiffness.push_back(row[3]);
    b.edge_stiffness.push_back(row[4]);
  }
  validate(b);
  return b;
}

}  // namespace fowtsim::flexbody
