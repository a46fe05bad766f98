#include "fowtsim/flexbody/elastodyn_blade.hpp"

#include "fowtsim/core/error.hpp"

#include <string>

namespace fowtsim::flexbody {
namespace {

[[noreturn]] void bad(const std::string& what, const std::string& message) {
  throw InputError({"flexbody.blade", std::nullopt, what, "see inputs/nrel5mw/blade_elastodyn.yaml"}, message);
}

}  // namespace

void validate(const ElastoDynBlade& b) {
  if (!(b.hub_radius >= 0.0 && b.tip_radius > b.hub_radius)) bad("hub_radius, tip_radius", "need 0 <= HubRad < TipRad");
  const std::size_t n = b.span_fraction.size();
  if (n < 2) bad("stations", "a blade needs at least 2 stations");
  if (b.twist_deg.size() != n || b.mass_density.size() != n || b.flap_stiffness.size() != n ||
      b.edge_stiffness.size() != n)
    bad("stations", "the station columns differ in length");
  if (b.span_fraction.front() != 0.0 || b.span_fraction.back() != 1.0)
    bad("BlFract", "stations must run from BlFract 0 (root) to 1 (tip)");
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0 && !(b.span_fraction[i] > b.span_fraction[i - 1])) bad("BlFract", "must be strictly increasing");
    if (!(b.mass_density[i] >= 0.0)) bad("BMassDen", "must be >= 0");
    if (!(b.flap_stiffness[i] > 0.0)) bad("FlpStff", "must be > 0");
    if (!(b.edge_stiffness[i] > 0.0)) bad("EdgStff", "must be > 0");
  }
  for (double f : {b.mass_factor, b.flap_stiffness_factor, b.edge_stiffness_factor, b.flap_stiffness_tuners[0],
                   b.flap_stiffness_tuners[1]})
    if (!(f > 0.0)) bad("AdjBlMs, AdjFlSt, AdjEdSt, FlStTunr", "factors must be > 0");
  for (double d : {b.flap_damping_percent[0], b.flap_damping_percent[1], b.edge_damping_percent})
    if (!(d >= 0.0)) bad("BldFlDmp, BldEdDmp", "damping must be >= 0 % of critical");
}

}  // namespace fowtsim::flexbody
