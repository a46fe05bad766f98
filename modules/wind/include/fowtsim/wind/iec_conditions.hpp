#pragma once
// The IEC 61400-1 wind-condition constants and closed forms, written once: ed. 3 (2005) subclauses
// and equation numbers (ed. 4 (2019) keeps every formula here unchanged; its subclauses are
// §6.2 Table 1, §6.3.2 normal and §6.3.3 extreme conditions).
// The turbulence generator, the deterministic wind events and the sweep presets all read them here.
#include "fowtsim/wind/params.hpp"

namespace fowtsim::wind {

// Reference wind speed V_ref [m/s] of wind turbine class I/II/III (Table 1): 50, 42.5, 37.5.
double reference_wind_speed(int iec_wind_class);

// Reference turbulence intensity I_ref [-] of category A/B/C (Table 1): 0.16, 0.14, 0.12.
double reference_turbulence_intensity(TurbulenceCategory category);

// Longitudinal turbulence scale parameter Λ1 [m] at hub height z_hub (eq. 5): 0.7 z_hub for
// z_hub <= 60 m, else 42 m.
double turbulence_scale_parameter(double hub_height_m);

// Hub-height longitudinal standard deviations σ1 [m/s]:
//   NTM (eq. 11): I_ref (0.75 V_hub + b), b = 5.6 m/s (ed. 4 keeps it as the 90 % quantile);
//   ETM (eq. 19): c I_ref (0.072 (V_ave/c + 3)(V_hub/c − 4) + 10), c = 2 m/s, V_ave = 0.2 V_ref;
//   turbulent EWM (ed. 3 §6.3.2.1, ed. 4 §6.3.3.2): 0.11 V_hub.
double ntm_sigma(TurbulenceCategory category, double v_hub_m_s);
double etm_sigma(TurbulenceCategory category, int iec_wind_class, double v_hub_m_s);
double ewm_sigma(double v_hub_m_s);

// Extreme wind speed model (ed. 3 §6.3.2.1, ed. 4 §6.3.3.2), hub-height values [m/s]; a height z
// takes (z/z_hub)^0.11:
//   steady (3-s gusts):   V_e50 = 1.4 V_ref,  V_e1 = 0.8 V_e50;
//   turbulent (10-min):   V_50  = V_ref,      V_1  = 0.8 V_50 (with σ1 = 0.11 V_hub).
inline constexpr double kEwmShearExponent = 0.11;  // α of the EWM profiles
double ewm_steady_50yr_speed(int iec_wind_class);
double ewm_steady_1yr_speed(int iec_wind_class);
double ewm_turbulent_50yr_speed(int iec_wind_class);
double ewm_turbulent_1yr_speed(int iec_wind_class);
// V(z) = V_hub (z / z_hub)^0.11 of any of the four above.
double ewm_profile_speed(double hub_speed_m_s, double z_m, double hub_height_m);

// Reduced wind speed model (IEC 61400-3 ed. 1 (2009) §6.3.2.1, used with the extreme wave height):
// V_red50 = 1.1 V_ref, V_red1 = 0.8 V_red50, hub-height values [m/s] (profile exponent 0.11).
double reduced_50yr_speed(int iec_wind_class);
double reduced_1yr_speed(int iec_wind_class);

}  // namespace fowtsim::wind
