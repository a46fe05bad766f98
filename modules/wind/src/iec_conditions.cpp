#include "fowtsim/wind/iec_conditions.hpp"

#include <cmath>

namespace fowtsim::wind {

double reference_wind_speed(int iec_wind_class) {
  if (iec_wind_class == 1) return 50.0;
  if (iec_wind_class == 2) return 42.5;
  return 37.5;
}

double reference_turbulence_intensity(TurbulenceCategory category) {
  switch (category) {
    case TurbulenceCategory::A: return 0.16;
    case TurbulenceCategory::B: return 0.14;
    case TurbulenceCategory::C: return 0.12;
  }
  return 0.14;
}

double turbulence_scale_parameter(double hub_height_m) { return hub_height_m <= 60.0 ? 0.7 * hub_height_m : 42.0; }

double ntm_sigma(TurbulenceCategory category, double v_hub_m_s) {
  return reference_turbulence_intensity(category) * (0.75 * v_hub_m_s + 5.6);
}

double etm_sigma(TurbulenceCategory category, int iec_wind_class, double v_hub_m_s) {
  const double c = 2.0;  // [m/s]
  const double v_ave = 0.2 * reference_wind_speed(iec_wind_class);
  return c * reference_turbulence_intensity(category) * (0.072 * (v_ave / c + 3.0) * (v_hub_m_s / c - 4.0) + 10.0);
}

double ewm_sigma(double v_hub_m_s) { return 0.11 * v_hub_m_s; }

double ewm_steady_50yr_speed(int iec_wind_class) { return 1.4 * reference_wind_speed(iec_wind_class); }
double ewm_steady_1yr_speed(int iec_wind_class) { return 0.8 * ewm_steady_50yr_speed(iec_wind_class); }
double ewm_turbulent_50yr_speed(int iec_wind_class) { return reference_wind_speed(iec_wind_class); }
double ewm_turbulent_1yr_speed(int iec_wind_class) { return 0.8 * ewm_turbulent_50yr_speed(iec_wind_class); }

double ewm_profile_speed(double hub_speed_m_s, double z_m, double hub_height_m) {
  return z_m <= 0.0 ? 0.0 : hub_speed_m_s * std::pow(z_m / hub_height_m, kEwmShearExponent);
}

double reduced_50yr_speed(int iec_wind_class) { return 1.1 * reference_wind_speed(iec_wind_class); }
double reduced_1yr_speed(int iec_wind_class) { return 0.8 * reduced_50yr_speed(iec_wind_class); }

}  // namespace fowtsim::wind
