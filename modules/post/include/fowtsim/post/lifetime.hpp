#pragma once
// Lifetime damage-equivalent loads over a set of runs weighted by a wind-speed distribution, as
// MLife extrapolates them (G. J. Hayman, "MLife Theory Manual for Version 1.00", NREL, 2012,
// §"Lifetime damage-equivalent loads"). Each run j of duration T_j stands for the fraction f_j of
// the design life T_life in which the hub-height mean wind speed lies in its bin; its cycles are
// extrapolated by f_j T_life / T_j:
//
//   f_j = P(V_j − ΔV/2 < V ≤ V_j + ΔV/2) / (number of runs in that bin),
//   D_life = Σ_j f_j (T_life / T_j) Σᵢ n_ji L_RF,ji^m,   n_eq,life = f_eq T_life,
//   DEL_life = (D_life / n_eq,life)^{1/m} = (Σ_j (f_j / T_j) Σᵢ n_ji L_RF,ji^m / f_eq)^{1/m}.
//
// T_life cancels in DEL_life but not in the damage sum D_life, which is kept for a Miner check.
// Time outside the bins (below the lowest, above the highest) does no damage, as in MLife when no
// parked or idling runs are given; `renormalise` scales the f_j to sum to one instead (pCrunch
// normalises its weights). Wind speed P(V ≤ v) = 1 − exp(−(v/A)^k), Weibull with shape k and scale
// A; IEC 61400-1 ed. 3 §6.3.1.1 takes a Rayleigh distribution (k = 2, A = 2 V_ave/√π,
// P = 1 − exp(−π/4 (v/V_ave)²)) with V_ave = 0.2 V_ref of the turbine class (10, 8.5, 7.5 m/s).
#include <span>
#include <vector>

namespace fowtsim::post {

struct WindSpeedDistribution {
  double shape_k = 2.0;    // Weibull shape k, – (> 0; 2 = Rayleigh)
  double scale_m_s = 0.0;  // Weibull scale A [m/s] (> 0)

  static WindSpeedDistribution weibull(double shape_k, double scale_m_s);
  // Weibull of shape k with mean speed V_ave: A = V_ave / Γ(1 + 1/k).
  static WindSpeedDistribution weibull_with_mean(double shape_k, double mean_speed_m_s);
  // Rayleigh with mean speed V_ave (IEC 61400-1): k = 2, A = 2 V_ave / √π.
  static WindSpeedDistribution rayleigh(double mean_speed_m_s);

  double cumulative_probability(double speed_m_s) const;  // P(V ≤ v), 0 for v ≤ 0
  double mean_speed_m_s() const;                          // A Γ(1 + 1/k)
};

// V_ave of an IEC 61400-1 ed. 3 wind turbine class (1, 2, 3): 0.2 V_ref = 10, 8.5, 7.5 m/s.
double iec_class_mean_speed_m_s(int wind_turbine_class);

// f_j for runs at the given mean wind speeds: bins of width bin_width_m_s centred on each distinct
// speed, shared equally by the runs at that speed. Throws InputError when two distinct speeds are
// closer than a bin width (their bins would overlap) or a bin reaches below 0 m/s.
std::vector<double> run_time_fractions(std::span<const double> wind_speeds_m_s, const WindSpeedDistribution& distribution,
                                       double bin_width_m_s, bool renormalise = false);

struct LifetimeRun {
  double time_fraction = 0.0;  // f_j, – (run_time_fractions)
  double duration_s = 0.0;     // T_j, analysed duration of the run [s] (> 0)
  double damage_sum = 0.0;     // Σᵢ n_ji L_RF,ji^m of the run (damage_equivalent_load.hpp)
};

struct LifetimeLoad {
  double damage_sum = 0.0;               // D_life, channel unit^m
  double damage_equivalent_load = 0.0;   // DEL_life, channel unit
};

// D_life and DEL_life for Wöhler exponent m over a design life of design_life_s.
LifetimeLoad lifetime_damage_equivalent_load(std::span<const LifetimeRun> runs, double wohler_exponent,
                                             double design_life_s, double equivalent_frequency_hz = 1.0);

inline constexpr double seconds_per_year = 365.25 * 86400.0;  // Julian year

}  // namespace fowtsim::post
