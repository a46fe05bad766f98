#pragma once
// IEC 61400-1 ed.3/ed.4 and IEC 61400-3-1 design load cases as sweep presets: what each one sets
// in the case decks. The numbers are the standard's; the sea states are the site's (the spec
// gives them), since the standards define them only as conditional statistics of the metocean data.
//   dlc1.1, dlc1.2  power production, normal turbulence model (NTM), normal sea state (NSS)
//   dlc1.6          power production, NTM, severe sea state (SSS)
//   dlc6.1          parked, steady extreme wind model (EWM) with the 50-year speed, yaw −8/0/+8°,
//                   50-year extreme sea state (ESS)
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "fowtsim/control/baseline_params.hpp"
#include "sweep/sweep_spec.hpp"

namespace fowtsim::driver::sweep {

// Realisations per wind speed of a preset: IEC 61400-1 asks for at least six 10-minute stochastic
// realisations per wind-speed bin for the turbulent load cases.
inline constexpr int kPresetSeeds = 6;

// V_ref of an IEC 61400-1 wind turbine class (ed.3 Table 1): 50, 42.5, 37.5 m/s.
double reference_wind_speed_m_s(int wind_class);
// I_ref of a turbulence category (ed.3 Table 1): A 0.16, B 0.14, C 0.12.
double reference_turbulence_intensity(const std::string& turbulence_class);
// NTM σ1 = I_ref (0.75 V_hub + b), b = 5.6 m/s (ed.3 §6.3.1.3): the longitudinal standard deviation
// the turbulence generator draws for a case (shown by --list).
double ntm_sigma_m_s(const std::string& turbulence_class, double hub_speed_m_s);
// Steady EWM at hub height, V_e50 = 1.4 V_ref (ed.3 §6.3.2.1; its profile (z/z_hub)^0.11).
double ewm50_hub_speed_m_s(int wind_class);
inline constexpr double kEwmShearExponent = 0.11;  // the EWM profile exponent (ed.3 §6.3.2.1)
// Yaw misalignments of DLC 6.1 with the steady EWM (ed.3 Table 2, note on DLC 6.1): ±8°.
inline const std::vector<double> kDlc61YawMisalignmentDeg = {-8.0, 0.0, 8.0};

// The kind of sea state a preset expects, for messages.
std::string_view preset_sea_state_kind(const std::string& preset);

// The base deck's controller, as a parked preset needs it: the feathered pitch is the deck's own
// upper pitch limit, so that the parked case decks stay inside the limits `fowtsim run` checks.
struct BaseController {
  std::string type;                 // controller.type ("baseline", "discon"); "" without a controller section
  double max_pitch_rad = control::BaselineParams{}.max_pitch_rad;  // controller.max_pitch_rad (its default if unset)
};

// Deck keys a preset sets in every case (key path, YAML value), before the case's own factors.
std::vector<std::pair<std::string, std::string>> preset_deck_keys(const std::string& preset, const TurbineClass& turbine,
                                                                  const BaseController& controller);

// Hs and Tp of a sea-state spec at a hub-height wind speed (kind table or relation, or fixed).
struct SeaState {
  double hs_m = 0.0;  // significant wave height [m]
  double tp_s = 0.0;  // peak period [s]
};
SeaState sea_state_at(const SeaStateSpec& sea, double wind_speed_m_s);

}  // namespace fowtsim::driver::sweep
