#include "fowtsim/mooring/params.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::mooring {
namespace {

// An anchor within this distance of the seabed counts as lying on it [m per m of depth].
constexpr double kSeabedTolerance = 1e-6;

bool on_seabed(const MooringParams& p, const LineParams& line) {
  return std::abs(line.anchor_m.z() + p.depth_m) <= kSeabedTolerance * std::max(p.depth_m, 1.0);
}

class Problems {
 public:
  void require(bool ok, const std::string& key, double found, const char* expected) {
    if (!ok) text_ += fmt::format("\n  {}: expected {}, found {}", key, expected, found);
  }
  void add(const std::string& key, const std::string& what) { text_ += fmt::format("\n  {}: {}", key, what); }
  void throw_if_any() const {
    if (!text_.empty()) {
      throw InputError({"mooring", std::nullopt, "mooring", "fix the listed keys of the mooring section"},
                       "invalid mooring parameters:" + text_);
    }
  }

 private:
  std::string text_;
};

bool finite(const Vec3& v) { return v.allFinite(); }

}  // namespace

LineModel line_model_from_name(std::string_view name) {
  if (name == "catenary") return LineModel::catenary;
  if (name == "taut") return LineModel::taut;
  throw InputError({"mooring", std::nullopt, "mooring.model", "use catenary or taut"},
                   fmt::format("mooring.model: expected catenary or taut, found '{}'", name));
}

const char* line_model_name(LineModel model) { return model == LineModel::taut ? "taut" : "catenary"; }

void validate(const MooringParams& p) {
  Problems problems;
  const bool catenary = p.model == LineModel::catenary;
  problems.require(!catenary || (std::isfinite(p.depth_m) && p.depth_m > 0.0), "mooring.depth_m", p.depth_m,
                   "a positive depth for the catenary model");
  problems.require(std::isfinite(p.water_density_kg_m3) && p.water_density_kg_m3 >= 0.0,
                   "mooring.water_density_kg_m3", p.water_density_kg_m3, "≥ 0");
  problems.require(std::isfinite(p.gravity_m_s2) && p.gravity_m_s2 > 0.0, "mooring.gravity_m_s2", p.gravity_m_s2,
                   "> 0");
  problems.require(std::isfinite(p.delta_yaw_stiffness_N_m_rad) && p.delta_yaw_stiffness_N_m_rad >= 0.0,
                   "mooring.delta_yaw_stiffness_N_m_rad", p.delta_yaw_stiffness_N_m_rad, "≥ 0");
  problems.require(std::isfinite(p.solver.tolerance) && p.solver.tolerance >= 1e-15 && p.solver.tolerance <= 1e-3,
                   "mooring.solver.tolerance", p.solver.tolerance, "in [1e-15, 1e-3] (fraction of the line length)");
  problems.require(p.solver.max_newton_iterations >= 1 && p.solver.max_newton_iterations <= 1000,
                   "mooring.solver.max_newton_iterations", p.solver.max_newton_iterations, "in [1, 1000]");
  problems.require(p.solver.max_bisection_iterations >= 60 && p.solver.max_bisection_iterations <= 10000,
                   "mooring.solver.max_bisection_iterations", p.solver.max_bisection_iterations,
                   "in [60, 10000]");
  if (p.lines.empty() || p.lines.size() > kMaxLines) {
    problems.add("mooring.lines", fmt::format("expected 1 to {} lines, found {}", kMaxLines, p.lines.size()));
  }
  for (std::size_t i = 0; i < p.lines.size(); ++i) {
    const LineParams& l = p.lines[i];
    const std::string key = fmt::format("mooring.lines[{}].", i);
    if (!finite(l.anchor_m)) problems.add(key + "anchor_m", "expected three finite numbers");
    if (!finite(l.fairlead_body_m)) problems.add(key + "fairlead_body_m", "expected three finite numbers");
    problems.require(std::isfinite(l.unstretched_length_m) && l.unstretched_length_m > 0.0,
                     key + "unstretched_length_m", l.unstretched_length_m, "> 0");
    problems.require(std::isfinite(l.ea_N) && l.ea_N > 0.0, key + "ea_N", l.ea_N, "> 0");
    if (!catenary) continue;
    problems.require(std::isfinite(l.mass_per_length_kg_m) && l.mass_per_length_kg_m > 0.0,
                     key + "mass_per_length_kg_m", l.mass_per_length_kg_m, "> 0");
    problems.require(std::isfinite(l.diameter_m) && l.diameter_m >= 0.0, key + "diameter_m", l.diameter_m, "≥ 0");
    problems.require(std::isfinite(l.seabed_friction) && l.seabed_friction >= 0.0, key + "seabed_friction",
                     l.seabed_friction, "≥ 0");
    if (std::isfinite(l.mass_per_length_kg_m) && std::isfinite(l.diameter_m) && l.mass_per_length_kg_m > 0.0 &&
        apparent_weight_N_m(p, l) <= 0.0) {
      problems.add(key + "mass_per_length_kg_m",
                   fmt::format("the line floats (apparent weight {:.6g} N/m ≤ 0); the catenary model needs a "
                               "line heavier than the water it displaces",
                               apparent_weight_N_m(p, l)));
    }
    if (finite(l.anchor_m) && std::isfinite(p.depth_m) && l.anchor_m.z() < -p.depth_m &&
        !on_seabed(p, l)) {
      problems.add(key + "anchor_m", fmt::format("anchor z = {} m lies below the seabed at −{} m",
                                                 l.anchor_m.z(), p.depth_m));
    }
  }
  problems.throw_if_any();
}

double apparent_weight_N_m(const MooringParams& p, const LineParams& line) {
  const double displaced = p.water_density_kg_m3 * std::numbers::pi / 4.0 * line.diameter_m * line.diameter_m;
  return (line.mass_per_length_kg_m - displaced) * p.gravity_m_s2;
}

CatenaryLine catenary_line(const MooringParams& p, std::size_t index) {
  const LineParams& l = p.lines.at(index);
  return {l.unstretched_length_m, apparent_weight_N_m(p, l), l.ea_N, l.seabed_friction, on_seabed(p, l)};
}

double unstretched_length_for_pretension(double chord_m, double pretension_N, double ea_N) {
  if (!(chord_m > 0.0) || !(pretension_N >= 0.0) || !(ea_N > 0.0) || !std::isfinite(chord_m + pretension_N + ea_N)) {
    throw InputError({"mooring", std::nullopt, "pretension", "chord and EA > 0, pretension ≥ 0"},
                     fmt::format("unstretched_length_for_pretension: chord {} m, pretension {} N, EA {} N",
                                 chord_m, pretension_N, ea_N));
  }
  return chord_m / (1.0 + pretension_N / ea_N);
}

}  // namespace fowtsim::mooring
