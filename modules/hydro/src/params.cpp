#include "fowtsim/hydro/params.hpp"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::hydro {
namespace {

// Collects every problem so the user sees them all at once (STYLE.md "Errors").
struct Problems {
  std::vector<std::string> lines;
  void require(bool ok, const std::string& key, double value, const char* expected) {
    if (!ok) lines.push_back(fmt::format("hydro.{} = {} (expected {})", key, value, expected));
  }
};

bool finite(const Vec3& v) { return v.allFinite(); }

void check_member(const MemberParams& m, int i, Problems& p) {
  const std::string k = fmt::format("members[{}].", i);
  if (!finite(m.end_a_body_m) || !finite(m.end_b_body_m)) {
    p.lines.push_back(fmt::format("hydro.{}end_a_body_m/end_b_body_m: non-finite coordinate", k));
  } else if ((m.end_b_body_m - m.end_a_body_m).norm() < 1e-9) {
    p.lines.push_back(fmt::format("hydro.{}end_b_body_m equals end_a_body_m (expected a member of "
                                  "positive length)", k));
  }
  p.require(m.diameter_a_m > 0.0 && std::isfinite(m.diameter_a_m), k + "diameter_a_m", m.diameter_a_m, "> 0 m");
  p.require(m.diameter_b_m > 0.0 && std::isfinite(m.diameter_b_m), k + "diameter_b_m", m.diameter_b_m, "> 0 m");
  const std::pair<const char*, double> coefficients[] = {
      {"cd", m.cd}, {"ca", m.ca}, {"axial_ca_a", m.axial_ca_a}, {"axial_cd_a", m.axial_cd_a},
      {"axial_cp_a", m.axial_cp_a}, {"axial_ca_b", m.axial_ca_b}, {"axial_cd_b", m.axial_cd_b},
      {"axial_cp_b", m.axial_cp_b}};
  for (const auto& [name, value] : coefficients) {
    p.require(value >= 0.0 && std::isfinite(value), k + name, value, ">= 0");
  }
  p.require(m.strips >= 1 && m.strips <= 100000, k + "strips", m.strips, "an integer in [1, 100000]");
}

}  // namespace

void validate(const Params& params) {
  Problems p;
  p.require(params.water_density_kg_m3 > 0.0 && std::isfinite(params.water_density_kg_m3),
            "water_density_kg_m3", params.water_density_kg_m3, "> 0 kg/m^3");
  p.require(params.gravity_m_s2 > 0.0 && std::isfinite(params.gravity_m_s2), "gravity_m_s2",
            params.gravity_m_s2, "> 0 m/s^2");
  if (params.members.empty()) p.lines.push_back("hydro.members: empty (expected at least one member)");
  for (int i = 0; i < static_cast<int>(params.members.size()); ++i) check_member(params.members[i], i, p);
  const CurrentParams& c = params.current;
  p.require(c.surface_speed_m_s >= 0.0 && std::isfinite(c.surface_speed_m_s), "current.surface_speed_m_s",
            c.surface_speed_m_s, ">= 0 m/s");
  p.require(std::isfinite(c.heading_rad), "current.heading_rad", c.heading_rad, "a finite angle");
  if (c.profile == CurrentParams::Profile::power_law) {
    p.require(c.reference_depth_m > 0.0 && std::isfinite(c.reference_depth_m), "current.reference_depth_m",
              c.reference_depth_m, "> 0 m for a power-law profile");
    p.require(c.power_law_exponent > 0.0 && std::isfinite(c.power_law_exponent),
              "current.power_law_exponent", c.power_law_exponent, "> 0");
  }
  if (!params.added_force.allFinite()) p.lines.push_back("hydro.added_force: non-finite entry");
  if (!params.added_stiffness.allFinite()) p.lines.push_back("hydro.added_stiffness: non-finite entry");
  if (!params.added_damping.allFinite()) p.lines.push_back("hydro.added_damping: non-finite entry");
  if (!params.added_quadratic_damping.allFinite()) {
    p.lines.push_back("hydro.added_quadratic_damping: non-finite entry");
  }
  if (params.hydrostatics == Hydrostatics::linear) {
    p.require(params.displaced_volume_m3 > 0.0 && std::isfinite(params.displaced_volume_m3), "displaced_volume_m3",
              params.displaced_volume_m3, "> 0 m^3 with linear hydrostatics");
    if (!params.hydrostatic_stiffness.allFinite()) p.lines.push_back("hydro.hydrostatic_stiffness: non-finite entry");
  }
  if (params.potential_flow && !params.potential_flow->radiation.added_mass_infinite_frequency.allFinite())
    p.lines.push_back("hydro.potential_flow: non-finite infinite-frequency added mass");
  p.require(params.hydrostatic_quadrature_points >= 2 && params.hydrostatic_quadrature_points <= 64,
            "hydrostatic_quadrature_points", params.hydrostatic_quadrature_points, "an integer in [2, 64]");
  if (p.lines.empty()) return;
  std::string message = fmt::format("{} invalid hydro parameter(s):", p.lines.size());
  for (const std::string& line : p.lines) message += "\n  " + line;
  throw InputError({"hydro", std::nullopt, "hydro", "fix the hydro section of the deck"}, message);
}

int node_count(const Params& params) {
  int n = 0;
  for (const MemberParams& m : params.members) n += m.strips + 2;
  return n;
}

int node_offset(const Params& params, int member) {
  int n = 0;
  for (int i = 0; i < member; ++i) n += params.members[i].strips + 2;
  return n;
}

}  // namespace fowtsim::hydro
