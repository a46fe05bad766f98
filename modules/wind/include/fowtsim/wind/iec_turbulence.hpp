#pragma once
// IEC 61400-1 ed. 3 (2005) turbulence model: standard deviations (§6.3), Kaimal spectra and the
// exponential coherence model (Annex B, eqs. B.1 and B.2). All spectra are one-sided, in Hz.
#include "fowtsim/wind/params.hpp"

namespace fowtsim::wind {

// Reference turbulence intensity I_ref (Table 1): A 0.16, B 0.14, C 0.12.
double reference_turbulence_intensity(TurbulenceCategory category);

// Reference wind speed V_ref of turbine class I/II/III (Table 1): 50, 42.5, 37.5 m/s.
double reference_wind_speed(int iec_wind_class);

// Longitudinal standard deviation sigma_1 [m/s] at hub speed v_hub [m/s]:
//   NTM (eq. 11): sigma_1 = I_ref (0.75 V_hub + b), b = 5.6 m/s
//   ETM (eq. 19): sigma_1 = c I_ref (0.072 (V_ave/c + 3)(V_hub/c − 4) + 10), c = 2 m/s, V_ave = 0.2 V_ref
double longitudinal_sigma(const TurbulenceParams& turbulence, double v_hub_m_s);

// Turbulence scale parameter Lambda_1 (eq. 5): 0.7 z for z <= 60 m, else 42 m.
double turbulence_scale_parameter(double hub_height_m);

struct KaimalComponent {
  double sigma_m_s;      // standard deviation sigma_k [m/s]: sigma_1, 0.8 sigma_1, 0.5 sigma_1
  double length_scale_m; // integral scale L_k [m]: 8.1, 2.7, 0.66 Lambda_1 (Table B.1)
};

struct KaimalModel {
  double v_hub_m_s;               // hub-height mean speed [m/s]
  KaimalComponent component[3];   // u, v, w
  double coherence_scale_m;       // L_c = 8.1 Lambda_1 [m] (eq. B.2)

  // One-sided Kaimal spectrum S_k(f) [m²/s² per Hz] (eq. B.1):
  //   f S_k / sigma_k² = 4 f L_k / V_hub / (1 + 6 f L_k / V_hub)^(5/3)
  double spectrum(int component_index, double frequency_hz) const;

  // Decay rate a(f) [1/m] of the u coherence Coh(r, f) = exp(−a r), from eq. B.2:
  //   Coh = exp(−12 sqrt((f r / V_hub)² + (0.12 r / L_c)²)) = exp(−r · 12 sqrt((f/V_hub)² + (0.12/L_c)²))
  double coherence_decay_per_m(double frequency_hz) const;
};

KaimalModel kaimal_model(const TurbulenceParams& turbulence, double v_hub_m_s, double hub_height_m);

}  // namespace fowtsim::wind
