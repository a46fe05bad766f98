#pragma once
// The design load cases of IEC 61400-1 ed. 4 (Table 2) as applied to floating turbines by
// IEC 61400-3-1 (Table 1) and IEC TS 61400-3-2, as sweep presets: what each one sets in its case
// decks (wind model and event, controller events, parked rotor), the factors it varies (wind
// speeds, yaw, event sign, event timing), its realisations, its analysis type (ultimate U and/or
// fatigue F) and its partial safety factor for loads γ_f (IEC 61400-1 ed. 4 Table 3: normal N 1.35,
// abnormal A 1.1; fatigue 1.0). The sea states are the site's: the spec gives them per group
// (normal NSS, severe SSS, extreme ESS), since the standards define them only as conditional
// statistics of the metocean data. The table of every preset: driver/app/sweep/README.md.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "fowtsim/control/baseline_params.hpp"
#include "sweep/sweep_spec.hpp"

namespace fowtsim::driver::sweep {

// Realisations per wind speed of a turbulent preset: IEC 61400-1 asks for at least six 10-minute
// stochastic realisations per wind-speed bin.
inline constexpr int kPresetSeeds = 6;

// The IEC numbers (V_ref, I_ref, σ1, the extreme speeds) are the wind module's
// (fowtsim/wind/iec_conditions.hpp); the normal wind profile's exponent is the presets' own.
inline constexpr double kNwpShearExponent = 0.2;   // the normal wind profile exponent (ed.3 §6.3.1.2)

// One design load case of the standard, as a preset.
struct PresetInfo {
  std::string_view name;       // "dlc2.3"
  std::string_view situation;  // design situation, e.g. "power production plus fault"
  std::string_view wind;       // wind condition, e.g. "EOG, V_r ± 2, V_out"
  std::string_view sea;        // sea state kind, e.g. "NSS"
  std::string_view other;      // events, yaw, parked rotor
  bool ultimate = false;       // analysis U
  bool fatigue = false;        // analysis F
  double partial_safety_factor = 1.35;  // γ_f of its ultimate loads (N 1.35, A 1.1); 1 for fatigue only
  int seeds = 1;               // realisations per factor combination by default
  // Fatigue of an event (start-up, shutdown, fault): weighted by its occurrences a year.
  bool events_per_year_needed() const { return fatigue && name != "dlc1.2" && name != "dlc6.4"; }
};

// Every preset, in the standard's order.
const std::vector<PresetInfo>& preset_table();
// The entry of a preset name (InputError for an unknown one; the spec's schema lists the names).
const PresetInfo& preset_info(std::string_view name);
std::vector<std::string> preset_names();

// The kind of sea state a preset expects, for messages.
std::string_view preset_sea_state_kind(const std::string& preset);

// The base deck's controller, as a parked preset needs it.
struct BaseController {
  std::string type;                 // controller.type ("baseline", "discon"); "" without a controller section
  double max_pitch_rad = control::BaselineParams{}.max_pitch_rad;  // controller.max_pitch_rad (its default if unset)
};

// A deck key a preset sets: a YAML scalar, or a flow-style YAML list or mapping (controller.events).
struct PresetKey {
  std::string key_path;
  std::string yaml_value;
  bool flow = false;  // yaml_value is flow-style YAML written as is
};

// A factor a preset varies: one value per case.
struct PresetFactor {
  std::string label;                 // name piece, e.g. "yaw", "dir", "tgl"
  std::vector<std::string> names;    // name piece per value (after the label)
  std::vector<std::vector<PresetKey>> keys;  // keys per value
};

// What a preset does to a group's cases.
struct PresetPlan {
  std::vector<PresetKey> keys;          // set in every case, before the group's own factors
  std::vector<PresetFactor> factors;    // varied, after the wind speed
  std::vector<double> wind_speeds_m_s;  // default hub-height speeds (empty: the preset's own, or none)
};

// The plan of `preset` for the spec's turbine: events at event_time_s (the analysis window's
// start), default wind speeds only when the group lists none (`speeds_given` false). Throws
// InputError naming the turbine key a default needs and the spec lacks.
PresetPlan preset_plan(const std::string& preset, const TurbineClass& turbine, const BaseController& controller, double event_time_s,
                       bool speeds_given);

// Hs and Tp of a sea-state spec at a hub-height wind speed (kind table or relation, or fixed).
struct SeaState {
  double hs_m = 0.0;  // significant wave height [m]
  double tp_s = 0.0;  // peak period [s]
};
SeaState sea_state_at(const SeaStateSpec& sea, double wind_speed_m_s);

}  // namespace fowtsim::driver::sweep
