#include "sweep/iec_presets.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/wind/iec_conditions.hpp"

namespace fowtsim::driver::sweep {

namespace {

constexpr double kN = 1.35;  // γ_f, normal design situations (IEC 61400-1 ed. 4 Table 3)
constexpr double kA = 1.1;   // γ_f, abnormal design situations
constexpr double kExtrapolated = 1.25;  // γ_f of DLC 1.1 (applies to the extrapolated load)
constexpr double kFatigue = 1.0;

// IEC 61400-1 ed. 4 Table 2 with IEC 61400-3-1 Table 1. Wind speeds: the bins V_in … V_out are
// 2 m/s wide; "V_r ± 2" is the standard's V_r − 2 and V_r + 2 m/s.
const std::vector<PresetInfo> kPresets = {
    {"dlc1.1", "power production", "NTM, V_in … V_out", "NSS", "for extreme loads on the rotor-nacelle assembly", true, false, kExtrapolated, kPresetSeeds},
    {"dlc1.2", "power production", "NTM, V_in … V_out", "NSS", "fatigue", false, true, kFatigue, kPresetSeeds},
    {"dlc1.3", "power production", "ETM, V_in … V_out", "NSS", "", true, false, kN, kPresetSeeds},
    {"dlc1.4", "power production", "ECD, V_r − 2, V_r, V_r + 2", "NSS", "direction change + and −", true, false, kN, 1},
    {"dlc1.5", "power production", "EWS, V_in … V_out", "NSS", "vertical and horizontal shear, + and −", true, false, kN, 1},
    {"dlc1.6", "power production", "NTM, V_in … V_out", "SSS", "", true, false, kN, kPresetSeeds},
    {"dlc2.1", "power production plus fault", "NTM, V_in … V_out", "NSS", "grid loss (normal control or grid fault), shutdown after it", true, false, kN, kPresetSeeds},
    {"dlc2.2", "power production plus fault", "NTM, V_in … V_out", "NSS", "blade 1 runs away to fine pitch (protection-system fault)", true, false, kA, kPresetSeeds},
    {"dlc2.3", "power production plus fault", "EOG, V_r ± 2, V_out", "NSS", "grid loss at the gust's start, dip and peak", true, false, kA, 1},
    {"dlc2.4", "power production plus fault", "NTM, V_in … V_out", "NSS", "grid loss, fatigue (give events_per_year)", false, true, kFatigue, kPresetSeeds},
    {"dlc3.1", "start-up", "NWP, V_in, V_r, V_out", "NSS", "start-up from idling, fatigue (give events_per_year)", false, true, kFatigue, 1},
    {"dlc3.2", "start-up", "EOG, V_in, V_r ± 2, V_out", "NSS", "start-up 10 s and 5 s before the gust and at it", true, false, kN, 1},
    {"dlc3.3", "start-up", "EDC, V_in, V_r ± 2, V_out", "NSS", "start-up as the direction changes, + and −", true, false, kN, 1},
    {"dlc4.1", "normal shutdown", "NWP, V_in, V_r, V_out", "NSS", "shutdown, fatigue (give events_per_year)", false, true, kFatigue, 1},
    {"dlc4.2", "normal shutdown", "EOG, V_r ± 2, V_out", "NSS", "shutdown at the gust's start, dip and peak", true, false, kN, 1},
    {"dlc5.1", "emergency stop", "NTM, V_r ± 2, V_out", "NSS", "emergency stop (fast pitch, shaft brake)", true, false, kN, kPresetSeeds},
    {"dlc6.1", "parked (idling)", "turbulent EWM, V_50 = V_ref", "ESS (50-year)", "yaw −8, 0, +8°", true, false, kN, kPresetSeeds},
    {"dlc6.2", "parked (idling)", "turbulent EWM, V_50 = V_ref", "ESS (50-year)", "grid loss: yaw −180 … 150° by 30°", true, false, kA, kPresetSeeds},
    {"dlc6.3", "parked (idling)", "turbulent EWM, V_1 = 0.8 V_ref", "ESS (1-year)", "extreme yaw −20, 0, +20°", true, false, kN, kPresetSeeds},
    {"dlc6.4", "parked (idling)", "NTM, V_hub < 0.7 V_ref", "NSS", "fatigue (give the speeds and the group's time fraction)", false, true, kFatigue, kPresetSeeds},
    {"dlc7.1", "parked plus fault", "turbulent EWM, V_1 = 0.8 V_ref", "ESS (1-year)", "blade 1 seized at fine pitch, yaw −8, 0, +8°", true, false, kA, kPresetSeeds},
};

// Timing of a controller event against a gust (EOG, T = 10.5 s, IEC 61400-1 ed. 4 eq. 17): at
// its start, in its dip (T/4) and at its peak (T/2), the instants that bound the worst case.
constexpr double kEogPeriod_s = 10.5;
const double kEogEventOffsets_s[] = {0.0, kEogPeriod_s / 4.0, kEogPeriod_s / 2.0};

std::string number_text(double value) { return fmt::format("{}", value); }

double required(const std::optional<double>& value, const char* key, const std::string& preset) {
  if (!value)
    throw InputError({"sweep", std::nullopt, std::string("turbine.") + key, "give it in the spec's turbine section"},
                     fmt::format("{} needs turbine.{} (its wind speeds or event size derive from it)", preset, key));
  return *value;
}

// Speeds V_in, V_in + 2, … up to V_out (V_out itself included when the last step falls short of it).
std::vector<double> operating_bins(double v_in, double v_out) {
  std::vector<double> speeds;
  for (double v = v_in; v < v_out - 1e-9; v += 2.0) speeds.push_back(v);
  speeds.push_back(v_out);
  return speeds;
}

PresetFactor signs(const std::string& label, const std::string& key) {
  return {label, {"+", "-"}, {{{key, "1"}}, {{key, "-1"}}}};
}

PresetFactor yaws(const std::vector<double>& degrees) {
  PresetFactor f{"yaw", {}, {}};
  for (const double d : degrees) {
    f.names.push_back(number_text(d));
    f.keys.push_back({{"wind.direction_deg", number_text(d)}});
  }
  return f;
}

// A controller event list in flow style: [{type: grid_loss, at_s: 130}].
std::string events(const std::string& body) { return "[{" + body + "}]"; }

}  // namespace

const std::vector<PresetInfo>& preset_table() { return kPresets; }

const PresetInfo& preset_info(std::string_view name) {
  for (const PresetInfo& p : kPresets)
    if (p.name == name) return p;
  throw InputError({"sweep", std::nullopt, "preset", "one of the presets `fowtsim --help-deck` lists"}, "unknown preset " + std::string(name));
}

std::vector<std::string> preset_names() {
  std::vector<std::string> names;
  for (const PresetInfo& p : kPresets) names.emplace_back(p.name);
  return names;
}

std::string_view preset_sea_state_kind(const std::string& preset) {
  const std::string_view sea = preset_info(preset).sea;
  if (sea == "SSS") return "the severe sea state (SSS)";
  if (sea == "ESS (50-year)") return "the 50-year extreme sea state (ESS)";
  if (sea == "ESS (1-year)") return "the 1-year extreme sea state";
  return "the normal sea state (NSS), E[Hs | V]";
}

PresetPlan preset_plan(const std::string& preset, const TurbineClass& turbine, const BaseController& controller, double event_time_s,
                       bool speeds_given) {
  PresetPlan plan;
  if (preset.empty()) return plan;
  const PresetInfo& info = preset_info(preset);
  auto set = [&](std::string key, std::string value, bool flow = false) { plan.keys.push_back({std::move(key), std::move(value), flow}); };
  const std::string hub = number_text(turbine.hub_height_m);
  // The turbine's speeds are needed only for default wind speeds (cleared below when the group lists its own).
  const auto v_in = [&] { return speeds_given ? 0.0 : required(turbine.cut_in_m_s, "cut_in_m_s", preset); };
  const auto v_r = [&] { return speeds_given ? 0.0 : required(turbine.rated_m_s, "rated_m_s", preset); };
  const auto v_out = [&] { return speeds_given ? 0.0 : required(turbine.cut_out_m_s, "cut_out_m_s", preset); };
  const std::string t_event = number_text(event_time_s);

  // Wind models.
  auto turbulent = [&](const char* model) {
    set("wind.model", "turbulent");
    set("wind.reference_height_m", hub);
    set("wind.turbulence.model", model);
    set("wind.turbulence.class", turbine.turbulence_class);
    set("wind.turbulence.iec_wind_class", number_text(turbine.wind_class));
  };
  auto normal_profile = [&] {  // NWP: steady power law, α = 0.2 (ed. 4 §6.3.2.2)
    set("wind.model", "power_law");
    set("wind.reference_height_m", hub);
    set("wind.shear_exponent", number_text(kNwpShearExponent));
  };
  auto wind_event = [&](const char* type) {
    set("wind.event.type", type);
    set("wind.event.start_s", t_event);
    set("wind.event.rotor_diameter_m", number_text(required(turbine.rotor_diameter_m, "rotor_diameter_m", preset)));
    set("wind.event.iec_wind_class", number_text(turbine.wind_class));
    set("wind.event.turbulence_class", turbine.turbulence_class);
  };
  // Turbulent EWM (ed. 4 §6.3.3.2): 10-minute mean V_50 = V_ref or V_1 = 0.8 V_ref at hub height,
  // σ1 = 0.11 V_hub, profile exponent 0.11.
  auto extreme_wind = [&](double speed) {
    turbulent("EWM");
    set("wind.speed_m_s", number_text(speed));
    set("wind.shear_exponent", number_text(wind::kEwmShearExponent));
  };
  // Idling: feathered at the deck's own upper pitch limit (90° for the NREL 5MW), generator off,
  // rotor free (controller.operating_mode: idling), starting at rest. With unsteady airfoils: on the
  // static polars, flexible blades in deep stall can vibrate edgewise without bound (the run's warning
  // says more).
  auto idling = [&] {
    set("controller.operating_mode", "idling");
    set("aero.unsteady_airfoil", "hgm");
    set("structure.initial_conditions.rotor_speed_rpm", "0");
    set("structure.initial_conditions.blade_pitch_deg", number_text(controller.max_pitch_rad * 180.0 / std::numbers::pi));
  };
  auto controller_event_times = [&](const std::string& type, std::initializer_list<double> offsets, const char* label) {
    PresetFactor f{label, {}, {}};
    for (const double dt : offsets) {
      f.names.push_back(number_text(dt));
      f.keys.push_back({{"controller.events", events(fmt::format("type: {}, at_s: {}", type, event_time_s + dt)), true}});
    }
    plan.factors.push_back(std::move(f));
  };

  const std::string_view name = info.name;
  if (name == "dlc1.1" || name == "dlc1.2" || name == "dlc1.6") {
    turbulent("NTM");
    plan.wind_speeds_m_s = operating_bins(v_in(), v_out());
  } else if (name == "dlc1.3") {
    turbulent("ETM");
    plan.wind_speeds_m_s = operating_bins(v_in(), v_out());
  } else if (name == "dlc1.4") {
    normal_profile();
    wind_event("ECD");
    plan.wind_speeds_m_s = {v_r() - 2.0, v_r(), v_r() + 2.0};
    plan.factors.push_back(signs("dir", "wind.event.sign"));
  } else if (name == "dlc1.5") {
    normal_profile();
    wind_event("EWS_vertical");
    plan.wind_speeds_m_s = operating_bins(v_in(), v_out());
    plan.factors.push_back({"ews",
                            {"v+", "v-", "h+", "h-"},
                            {{{"wind.event.type", "EWS_vertical"}, {"wind.event.sign", "1"}},
                             {{"wind.event.type", "EWS_vertical"}, {"wind.event.sign", "-1"}},
                             {{"wind.event.type", "EWS_horizontal"}, {"wind.event.sign", "1"}},
                             {{"wind.event.type", "EWS_horizontal"}, {"wind.event.sign", "-1"}}}});
  } else if (name == "dlc2.1" || name == "dlc2.4") {
    turbulent("NTM");
    plan.wind_speeds_m_s = operating_bins(v_in(), v_out());
    set("controller.events", events(fmt::format("type: grid_loss, at_s: {}", event_time_s)), true);
  } else if (name == "dlc2.2") {
    turbulent("NTM");
    plan.wind_speeds_m_s = operating_bins(v_in(), v_out());
    set("controller.events", events(fmt::format("type: pitch_runaway, blade: 1, at_s: {}", event_time_s)), true);
  } else if (name == "dlc2.3" || name == "dlc4.2") {
    normal_profile();
    wind_event("EOG");
    plan.wind_speeds_m_s = {v_r() - 2.0, v_r() + 2.0, v_out()};
    controller_event_times(name == "dlc2.3" ? "grid_loss" : "shutdown",
                           {kEogEventOffsets_s[0], kEogEventOffsets_s[1], kEogEventOffsets_s[2]}, "t");
  } else if (name == "dlc3.1" || name == "dlc4.1") {
    normal_profile();
    plan.wind_speeds_m_s = {v_in(), v_r(), v_out()};
    if (name == "dlc3.1") idling();
    set("controller.events", events(fmt::format("type: {}, at_s: {}", name == "dlc3.1" ? "startup" : "shutdown", event_time_s)), true);
  } else if (name == "dlc3.2") {
    normal_profile();
    wind_event("EOG");
    idling();
    plan.wind_speeds_m_s = {v_in(), v_r() - 2.0, v_r() + 2.0, v_out()};
    controller_event_times("startup", {-10.0, -5.0, 0.0}, "t");
  } else if (name == "dlc3.3") {
    normal_profile();
    wind_event("EDC");
    idling();
    plan.wind_speeds_m_s = {v_in(), v_r() - 2.0, v_r() + 2.0, v_out()};
    plan.factors.push_back(signs("dir", "wind.event.sign"));
    set("controller.events", events(fmt::format("type: startup, at_s: {}", event_time_s)), true);
  } else if (name == "dlc5.1") {
    turbulent("NTM");
    plan.wind_speeds_m_s = {v_r() - 2.0, v_r() + 2.0, v_out()};
    set("controller.events", events(fmt::format("type: emergency_stop, at_s: {}", event_time_s)), true);
  } else if (name == "dlc6.1" || name == "dlc6.2") {
    extreme_wind(wind::ewm_turbulent_50yr_speed(turbine.wind_class));
    idling();
    if (name == "dlc6.1") {
      plan.factors.push_back(yaws({-8.0, 0.0, 8.0}));
    } else {
      std::vector<double> all;
      for (int d = -180; d < 180; d += 30) all.push_back(d);
      plan.factors.push_back(yaws(all));
    }
  } else if (name == "dlc6.3") {
    extreme_wind(wind::ewm_turbulent_1yr_speed(turbine.wind_class));
    idling();
    plan.factors.push_back(yaws({-20.0, 0.0, 20.0}));
  } else if (name == "dlc6.4") {
    turbulent("NTM");
    idling();
  } else if (name == "dlc7.1") {
    extreme_wind(wind::ewm_turbulent_1yr_speed(turbine.wind_class));
    idling();
    // Seized at fine pitch: blade 1 runs to 0° from the start and stays there.
    set("controller.events", events("type: pitch_runaway, blade: 1, at_s: 0, target_deg: 0"), true);
    plan.factors.push_back(yaws({-8.0, 0.0, 8.0}));
  }
  if (speeds_given) plan.wind_speeds_m_s.clear();
  return plan;
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
