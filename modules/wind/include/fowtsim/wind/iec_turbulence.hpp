#pragma once
// IEC 61400-1 ed. 3 (2005) turbulence model: standard deviations (§6.3), Kaimal spectra and the
// exponential coherence model (Annex B, eqs. B.1 and B.2). All spectra are one-sided, in Hz. The
// constants (V_ref, I_ref, Λ1, the σ1 of each model) are in iec_conditions.hpp.
#include "fowtsim/wind/iec_conditions.hpp"
#include "fowtsim/wind/params.hpp"

namespace fowtsim::wind {

// Longitudinal standard deviation sigma_1 [m/s] at hub speed v_hub [m/s] of the deck's model:
// ntm_sigma, etm_sigma or ewm_sigma (iec_conditions.hpp).
double longitudinal_sigma(const TurbulenceParams& turbulence, double v_hub_m_s);

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
