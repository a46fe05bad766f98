#pragma once
// Short-term damage-equivalent loads as MLife defines them (G. J. Hayman, "MLife Theory Manual for
// Version 1.00", NREL, Oct. 2012, §"Short-term damage-equivalent loads"):
//
//   DEL = ( Σᵢ nᵢ · L_RFᵢ^m / n_eq )^{1/m},   n_eq = f_eq · T,
//
// nᵢ the rainflow count of cycle i (rainflow.hpp), m the Wöhler (S-N slope) exponent, T the
// duration of the record and f_eq the equivalent frequency (1 Hz by default, as MLife and the
// seed's Table 4.3). L_RF is the cycle's load range, or with the Goodman correction the range that
// does as much damage at the fixed mean L_MF:
//
//   L_RFᵢ = L_Rᵢ · (L_ult − |L_MF|) / (L_ult − |L_Mᵢ|),
//
// L_Mᵢ the cycle mean and L_ult the ultimate load (MLife, Goodman exponent 1). DEL is a range
// (peak to valley), so a sine of amplitude A gives DEL = 2A · (f T / n_eq)^{1/m}. No binning: every
// cycle enters with its exact range and mean (MLife bins ranges; binning moves each range to its
// bin centre, an error up to half a bin width per cycle, amplified m-fold in the damage sum).
#include <optional>
#include <span>

#include "fowtsim/post/rainflow.hpp"

namespace fowtsim::post {

struct FatigueParams {
  double wohler_exponent = 3.0;          // m, S-N slope exponent, – (> 0; 3–5 steel, ~10 composites)
  std::optional<double> ultimate_load;   // L_ult, channel unit (> 0); set = Goodman correction on
  double goodman_fixed_mean = 0.0;       // L_MF, channel unit: the mean all cycles are corrected to
  double equivalent_frequency_hz = 1.0;  // f_eq [Hz] (> 0)
};

// L_RF of one cycle: its range, Goodman-corrected when params.ultimate_load is set. Throws
// InputError when a cycle mean or L_MF reaches the ultimate load (the correction diverges).
double fatigue_range(const RainflowCycle& cycle, const FatigueParams& params);

// Σ nᵢ L_RFᵢ^m: the damage sum (Miner's damage times the S-N constant), what lifetime DELs add up.
double damage_sum(std::span<const RainflowCycle> cycles, const FatigueParams& params);

// DEL = (damage_sum / (f_eq T))^{1/m} for a record of duration_s (> 0).
double damage_equivalent_load(std::span<const RainflowCycle> cycles, double duration_s, const FatigueParams& params);

}  // namespace fowtsim::post
