#include "fowtsim/aero/params.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::aero {
namespace {

// Collects every problem so the user sees them all at once (STYLE.md "Errors").
struct Problems {
  std::vector<std::string> lines;
  void require(bool ok, const std::string& key, double value, const char* expected) {
    if (!ok) lines.push_back(fmt::format("aero.{} = {} (expected {})", key, value, expected));
  }
};

bool finite(double x) { return std::isfinite(x); }

void check_blade(const Params& params, Problems& p) {
  const int n = nodes_per_blade(params);
  if (n < 2) p.lines.push_back(fmt::format("aero.blade.nodes: {} rows (expected at least 2)", n));
  const int airfoils = static_cast<int>(params.airfoils.size());
  for (int i = 0; i < n; ++i) {
    const BladeNodeParams& b = params.blade[i];
    const std::string k = fmt::format("blade.nodes[{}].", i);
    p.require(finite(b.span_m) && b.span_m >= 0.0, k + "span_m", b.span_m, "a finite value >= 0 m");
    if (i > 0) {
      p.require(b.span_m > params.blade[i - 1].span_m, k + "span_m", b.span_m,
                "strictly increasing from root to tip");
    }
    p.require(finite(b.curve_ac_m), k + "curve_ac_m", b.curve_ac_m, "a finite offset in m");
    p.require(finite(b.sweep_ac_m), k + "sweep_ac_m", b.sweep_ac_m, "a finite offset in m");
    p.require(finite(b.curve_angle_rad) && std::abs(b.curve_angle_rad) < 0.5 * std::numbers::pi,
              k + "curve_angle", b.curve_angle_rad, "a finite angle below 90 deg in magnitude (rad shown)");
    p.require(finite(b.twist_rad), k + "twist", b.twist_rad, "a finite angle (rad shown)");
    p.require(finite(b.chord_m) && b.chord_m > 0.0, k + "chord_m", b.chord_m, "> 0 m");
    p.require(b.airfoil >= 0 && b.airfoil < airfoils, k + "airfoil", b.airfoil,
              "the index of a listed airfoil");
  }
}

void check_tower(const Params& params, Problems& p) {
  const bool used = params.tower_potential != TowerPotential::none ||
                    params.tower_shadow != TowerShadow::none || params.tower_drag;
  if (!used) return;
  const int n = static_cast<int>(params.tower.size());
  if (n < 2) {
    p.lines.push_back(fmt::format("aero.tower.nodes: {} rows (expected at least 2 when "
                                  "tower_potential, tower_shadow or tower_drag is on)", n));
  }
  for (int i = 0; i < n; ++i) {
    const TowerNodeParams& t = params.tower[i];
    const std::string k = fmt::format("tower.nodes[{}].", i);
    p.require(finite(t.elevation_m), k + "elevation_m", t.elevation_m, "a finite value in m");
    if (i > 0) {
      p.require(t.elevation_m > params.tower[i - 1].elevation_m, k + "elevation_m", t.elevation_m,
                "strictly increasing from base to top");
    }
    p.require(finite(t.diameter_m) && t.diameter_m > 0.0, k + "diameter_m", t.diameter_m, "> 0 m");
    p.require(finite(t.drag_coefficient) && t.drag_coefficient >= 0.0, k + "drag_coefficient",
              t.drag_coefficient, ">= 0");
    if (params.tower_shadow == TowerShadow::eames) {
      p.require(finite(t.turbulence_intensity) && t.turbulence_intensity > 0.0,
                k + "turbulence_intensity", t.turbulence_intensity, "> 0 for the Eames shadow");
    }
  }
}

}  // namespace

void validate(const Params& params) {
  Problems p;
  p.require(finite(params.air_density_kg_m3) && params.air_density_kg_m3 > 0.0, "air_density_kg_m3",
            params.air_density_kg_m3, "> 0 kg/m^3");
  p.require(params.number_of_blades >= 1 && params.number_of_blades <= 10, "number_of_blades",
            params.number_of_blades, "an integer in [1, 10]");
  if (params.airfoils.empty()) p.lines.push_back("aero.airfoils: empty (expected at least one polar)");
  check_blade(params, p);
  p.require(finite(params.skew_factor) && params.skew_factor >= 0.0, "skew_factor", params.skew_factor,
            ">= 0 (15*pi/32 is the Pitt-Peters value)");
  check_tower(params, p);
  p.require(finite(params.ua_pressure_time_constant) && params.ua_pressure_time_constant > 0.0,
            "ua_pressure_time_constant", params.ua_pressure_time_constant, "> 0 (HGM: 1.5)");
  p.require(finite(params.ua_separation_time_constant) && params.ua_separation_time_constant > 0.0,
            "ua_separation_time_constant", params.ua_separation_time_constant, "> 0 (HGM: 6.0)");
  p.require(finite(params.ua_cutout_rad) && params.ua_cutout_rad >= 5.0 * std::numbers::pi / 180.0 &&
                params.ua_cutout_rad <= 0.5 * std::numbers::pi,
            "ua_cutout_deg", params.ua_cutout_rad * 180.0 / std::numbers::pi, "in [5, 90] degrees (AeroDyn: 45)");
  if (params.output_nodes.size() > 9) {
    p.lines.push_back(fmt::format("aero.output_nodes: {} entries (expected at most 9, as AeroDyn's "
                                  "BlOutNd)", params.output_nodes.size()));
  }
  for (int node : params.output_nodes) {
    p.require(node >= 1 && node <= nodes_per_blade(params), "output_nodes[]", node,
              "a 1-based blade node number");
  }
  if (p.lines.empty()) return;
  std::string message = fmt::format("{} invalid aero parameter(s):", p.lines.size());
  for (const std::string& line : p.lines) message += "\n  " + line;
  throw InputError({"aero", std::nullopt, "aero", "fix the aero section of the deck"}, message);
}

}  // namespace fowtsim::aero
