// Lifetime DELs: wind-speed probabilities and the MLife extrapolation by hand.
#include <cmath>
#include <numbers>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/post/lifetime.hpp"

using namespace fowtsim::post;

TEST_CASE("Rayleigh bin probabilities equal differences of exp(-π/4 (v/Vave)²)", "[verification]") {
  // IEC 61400-1 ed. 3 eq. (8): P_R(V) = 1 − exp(−π (V/(2 V_ave))²); bins of 4 m/s around 8, 12, 16.
  const WindSpeedDistribution rayleigh = WindSpeedDistribution::rayleigh(iec_class_mean_speed_m_s(1));
  const auto survival = [](double v) { return std::exp(-std::numbers::pi / 4.0 * (v / 10.0) * (v / 10.0)); };
  const std::vector<double> speeds{8.0, 12.0, 16.0};
  const std::vector<double> fractions = run_time_fractions(speeds, rayleigh, 4.0);
  // 5e-15 relative: the same closed form through pow and expm1 (measured ≤ 4.1e-16).
  CHECK(fractions[0] == Approx(survival(6.0) - survival(10.0)).epsilon(5e-15));
  CHECK(fractions[1] == Approx(survival(10.0) - survival(14.0)).epsilon(5e-15));
  CHECK(fractions[2] == Approx(survival(14.0) - survival(18.0)).epsilon(5e-15));
  // Mean speeds through Γ(1 + 1/k) (measured 1.8e-16 and 0): 2e-15.
  CHECK(rayleigh.mean_speed_m_s() == Approx(10.0).epsilon(2e-15));
  CHECK(WindSpeedDistribution::weibull_with_mean(2.5, 9.0).mean_speed_m_s() == Approx(9.0).epsilon(2e-15));
  // Renormalised fractions sum to one (pCrunch's weighting).
  const std::vector<double> normalised = run_time_fractions(speeds, rayleigh, 4.0, true);
  CHECK(normalised[0] + normalised[1] + normalised[2] == Approx(1.0).epsilon(2e-15));  // measured 0
}

TEST_CASE("lifetime DEL of three bins equals the MLife extrapolation by hand", "[verification]") {
  // Runs: 8 m/s (two seeds of 600 s, sharing the bin), 12 m/s (600 s), 16 m/s (300 s); Weibull k = 2.2,
  // A = 11 m/s; bins 4 m/s wide; m = 4; 20 years; f_eq = 1 Hz. MLife theory manual: DEL_life =
  // (Σ_j f_j (T_life/T_j) D_j / (f_eq T_life))^{1/m} with f_j = P(bin)/(runs in the bin).
  const WindSpeedDistribution weibull = WindSpeedDistribution::weibull(2.2, 11.0);
  const std::vector<double> speeds{8.0, 8.0, 12.0, 16.0};
  const std::vector<double> durations{600.0, 600.0, 600.0, 300.0};
  const std::vector<double> damage_sums{1.0e6, 1.4e6, 3.0e6, 2.5e6};
  const std::vector<double> fractions = run_time_fractions(speeds, weibull, 4.0);
  const auto cdf = [](double v) { return 1.0 - std::exp(-std::pow(v / 11.0, 2.2)); };
  const double p8 = cdf(10.0) - cdf(6.0), p12 = cdf(14.0) - cdf(10.0), p16 = cdf(18.0) - cdf(14.0);
  // 2e-15: 1 − exp against expm1 (measured 0).
  CHECK(fractions[0] == Approx(p8 / 2).epsilon(2e-15));
  CHECK(fractions[1] == fractions[0]);
  CHECK(fractions[3] == Approx(p16).epsilon(2e-15));

  std::vector<LifetimeRun> runs;
  for (std::size_t j = 0; j < speeds.size(); ++j) runs.push_back({fractions[j], durations[j], damage_sums[j]});
  const double life_s = 20.0 * seconds_per_year;
  const LifetimeLoad load = lifetime_damage_equivalent_load(runs, 4.0, life_s);
  const double hand_damage = life_s * (p8 / 2 * 1.0e6 / 600 + p8 / 2 * 1.4e6 / 600 + p12 * 3.0e6 / 600 + p16 * 2.5e6 / 300);
  // 2e-15: four terms in another order (measured 1.3e-16 and 0).
  CHECK(load.damage_sum == Approx(hand_damage).epsilon(2e-15));
  CHECK(load.damage_equivalent_load == Approx(std::pow(hand_damage / life_s, 0.25)).epsilon(2e-15));
  // T_life cancels in the DEL: 25 years give the same DEL, 25/20 of the damage.
  const LifetimeLoad longer = lifetime_damage_equivalent_load(runs, 4.0, 25.0 * seconds_per_year);
  CHECK(longer.damage_equivalent_load == Approx(load.damage_equivalent_load).epsilon(2e-15));  // measured 1.2e-16
  CHECK(longer.damage_sum == Approx(1.25 * load.damage_sum).epsilon(2e-15));                  // measured 2.0e-16
}

TEST_CASE("overlapping wind-speed bins and unknown classes are refused", "[unit]") {
  const WindSpeedDistribution rayleigh = WindSpeedDistribution::rayleigh(8.5);
  CHECK_THROWS_AS(run_time_fractions(std::vector<double>{8.0, 9.0}, rayleigh, 2.0), fowtsim::InputError);
  CHECK_THROWS_AS(run_time_fractions(std::vector<double>{0.5}, rayleigh, 2.0), fowtsim::InputError);
  CHECK_NOTHROW(run_time_fractions(std::vector<double>{8.0, 10.0}, rayleigh, 2.0));  // bins touch
  CHECK_THROWS_AS(iec_class_mean_speed_m_s(4), fowtsim::InputError);
  CHECK_THROWS_AS(WindSpeedDistribution::weibull(0.0, 10.0), fowtsim::InputError);
}
