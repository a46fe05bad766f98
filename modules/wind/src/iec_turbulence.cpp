#include "fowtsim/wind/iec_turbulence.hpp"

#include <cmath>

namespace fowtsim::wind {

double longitudinal_sigma(const TurbulenceParams& turbulence, double v_hub_m_s) {
  switch (turbulence.model) {
    case TurbulenceModel::NTM: return ntm_sigma(turbulence.category, v_hub_m_s);
    case TurbulenceModel::ETM: return etm_sigma(turbulence.category, turbulence.iec_wind_class, v_hub_m_s);
    case TurbulenceModel::EWM: return ewm_sigma(v_hub_m_s);
  }
  return ntm_sigma(turbulence.category, v_hub_m_s);
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
