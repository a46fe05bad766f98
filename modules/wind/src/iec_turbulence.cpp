#include "fowtsim/wind/iec_turbulence.hpp"

#include <cmath>

namespace fowtsim::wind {

double reference_turbulence_intensity(TurbulenceCategory category) {
  switch (category) {
    case TurbulenceCategory::A: return 0.16;
    case TurbulenceCategory::B: return 0.14;
    case TurbulenceCategory::C: return 0.12;
  }
  return 0.14;
}

double reference_wind_speed(int iec_wind_class) {
  if (iec_wind_class == 1) return 50.0;
  if (iec_wind_class == 2) return 42.5;
  return 37.5;
}

double longitudinal_sigma(const TurbulenceParams& turbulence, double v_hub_m_s) {
  const double i_ref = reference_turbulence_intensity(turbulence.category);
  if (turbulence.model == TurbulenceModel::NTM) return i_ref * (0.75 * v_hub_m_s + 5.6);
  const double c = 2.0;  // [m/s], IEC 61400-1 ed. 3 eq. 19
  const double v_ave = 0.2 * reference_wind_speed(turbulence.iec_wind_class);
  return c * i_ref * (0.072 * (v_ave / c + 3.0) * (v_hub_m_s / c - 4.0) + 10.0);
}

double turbulence_scale_parameter(double hub_height_m) {
  return hub_height_m <= 60.0 ? 0.7 * hub_height_m : 42.0;
}

double KaimalModel::spectrum(int k, double f) const {
  const double sigma = component[k].sigma_m_s;
  const double l_over_v = component[k].length_scale_m / v_hub_m_s;
  return sigma * sigma * 4.0 * l_over_v / std::pow(1.0 + 6.0 * f * l_over_v, 5.0 / 3.0);
}

double KaimalModel::coherence_decay_per_m(double f) const {
  const double a = f / v_hub_m_s;
  const double b = 0.12 / coherence_scale_m;
  return 12.0 * std::sqrt(a * a + b * b);
}

KaimalModel kaimal_model(const TurbulenceParams& turbulence, double v_hub_m_s, double hub_height_m) {
  const double sigma1 = longitudinal_sigma(turbulence, v_hub_m_s);
  const double lambda1 = turbulence_scale_parameter(hub_height_m);
  KaimalModel model{};
  model.v_hub_m_s = v_hub_m_s;
  model.component[0] = {sigma1, 8.1 * lambda1};
  model.component[1] = {0.8 * sigma1, 2.7 * lambda1};
  model.component[2] = {0.5 * sigma1, 0.66 * lambda1};
  model.coherence_scale_m = 8.1 * lambda1;
  return model;
}

}  // namespace fowtsim::wind
