#include "sweep/iec_presets.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace fowtsim::driver::sweep {

double reference_wind_speed_m_s(int wind_class) {
  constexpr double v_ref[] = {50.0, 42.5, 37.5};
  return v_ref[std::clamp(wind_class, 1, 3) - 1];
}

double reference_turbulence_intensity(const std::string& turbulence_class) {
  if (turbulence_class == "A") return 0.16;
  if (turbulence_class == "C") return 0.12;
  return 0.14;
}

double ntm_sigma_m_s(const std::string& turbulence_class, double hub_speed_m_s) {
  return reference_turbulence_intensity(turbulence_class) * (0.75 * hub_speed_m_s + 5.6);
}

double ewm50_hub_speed_m_s(int wind_class) { return 1.4 * reference_wind_speed_m_s(wind_class); }

std::string_view preset_sea_state_kind(const std::string& preset) {
  if (preset == "dlc1.6") return "the severe sea state (SSS)";
  if (preset == "dlc6.1") return "the 50-year extreme sea state (ESS)";
  return "the normal sea state (NSS), E[Hs | V]";
}

std::vector<std::pair<std::string, std::string>> preset_deck_keys(const std::string& preset, const TurbineClass& turbine,
                                                                  const BaseController& controller) {
  if (preset.rfind("dlc1.", 0) == 0)
    return {{"wind.model", "turbulent"},
            {"wind.reference_height_m", fmt::format("{}", turbine.hub_height_m)},
            {"wind.turbulence.model", "NTM"},
            {"wind.turbulence.class", turbine.turbulence_class}};
  if (preset != "dlc6.1") return {};
  // Parked: rotor held still, blades feathered at the deck's own pitch limit (90° for the NREL
  // 5MW: 1.570796 rad), so the case stays inside the limits the controller checks. The baseline
  // controller would pitch the blades back to fine pitch at zero speed, so its lower pitch limit
  // is raised to that feather angle too (equal limits hold the pitch there). A DISCON controller
  // must be parked by its own input file: its limits are left alone.
  const double feather_rad = controller.max_pitch_rad;
  std::vector<std::pair<std::string, std::string>> keys = {
      {"wind.model", "power_law"},
      {"wind.speed_m_s", fmt::format("{}", ewm50_hub_speed_m_s(turbine.wind_class))},
      {"wind.reference_height_m", fmt::format("{}", turbine.hub_height_m)},
      {"wind.shear_exponent", fmt::format("{}", kEwmShearExponent)},
      {"structure.initial_conditions.rotor_speed_rpm", "0"},
      {"structure.initial_conditions.blade_pitch_deg", fmt::format("{}", feather_rad * 180.0 / std::numbers::pi)},
      {"structure.degrees_of_freedom.rotor_speed", "held"}};
  if (controller.type == "baseline") keys.emplace_back("controller.min_pitch_rad", fmt::format("{}", feather_rad));
  return keys;
}

SeaState sea_state_at(const SeaStateSpec& sea, double v) {
  switch (sea.kind) {
    case SeaStateSpec::Kind::fixed: return {sea.hs_m, sea.tp_s};
    case SeaStateSpec::Kind::table: {
      // Rows are increasing in speed and the spec checked v lies inside them.
      const auto upper = std::upper_bound(sea.table.begin(), sea.table.end(), v,
                                          [](double x, const SeaStateTableRow& r) { return x < r.wind_speed_m_s; });
      if (upper == sea.table.end()) return {sea.table.back().hs_m, sea.table.back().tp_s};
      const SeaStateTableRow& b = *upper;
      const SeaStateTableRow& a = *(upper - 1);
      const double w = (v - a.wind_speed_m_s) / (b.wind_speed_m_s - a.wind_speed_m_s);
      return {a.hs_m + w * (b.hs_m - a.hs_m), a.tp_s + w * (b.tp_s - a.tp_s)};
    }
    case SeaStateSpec::Kind::relation: {
      double hs = 0.0, power = 1.0;
      for (const double c : sea.hs_coefficients) {
        hs += c * power;
        power *= v;
      }
      hs = std::max(hs, 0.0);
      constexpr double g = 9.80665;  // standard gravity [m/s²], as the waves deck's default
      return {hs, sea.tp_factor * std::sqrt(hs / g)};
    }
    case SeaStateSpec::Kind::from_base_deck: break;
  }
  return {};
}

}  // namespace fowtsim::driver::sweep
