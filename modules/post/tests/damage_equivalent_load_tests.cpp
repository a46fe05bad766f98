// Damage-equivalent loads against hand sums and the closed form of a sine.
#include <cmath>
#include <numbers>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/post/damage_equivalent_load.hpp"

using namespace fowtsim::post;

namespace {

// mean + A cos(2π f t) sampled 64 times per period over `periods` whole periods, both ends included:
// turning points A, −A, …, A exactly (the phase is taken modulo one period), so rainflow finds
// periods − 1 full cycles of range 2A and a residue A, −A, A of two half cycles: f T cycles in all.
std::vector<double> sampled_cosine(double amplitude, double mean, int periods) {
  constexpr int per_period = 64;
  std::vector<double> v;
  for (int j = 0; j <= periods * per_period; ++j)
    v.push_back(mean + amplitude * std::cos(2.0 * std::numbers::pi * (j % per_period) / per_period));
  return v;
}

}  // namespace

TEST_CASE("DEL of the ASTM E1049-85 example equals the hand sum of its cycle table", "[verification]") {
  // Cycle table (ASTM E1049-85 Table 4): ranges 3, 4, 6, 8, 9 with counts 0.5, 1.5, 0.5, 1.0, 0.5;
  // DEL = (Σ nᵢ Lᵢ^m / n_eq)^{1/m} (MLife theory manual), n_eq = f_eq T with f_eq = 1 Hz.
  const std::vector<RainflowCycle> cycles = rainflow_cycles(std::vector<double>{-2, 1, -3, 5, -1, 3, -4, 4, -2});
  for (const double m : {3.0, 4.0, 6.0}) {
    const double hand_sum = 0.5 * std::pow(3, m) + 1.5 * std::pow(4, m) + 0.5 * std::pow(6, m) + 1.0 * std::pow(8, m) +
                            0.5 * std::pow(9, m);
    for (const double n_eq : {1.0, 17.0}) {
      const FatigueParams params{m, std::nullopt, 0.0, 1.0};
      // Exact in exact arithmetic; 2e-15 for the same sum in another order (measured 0).
      CHECK(damage_equivalent_load(cycles, n_eq, params) == Approx(std::pow(hand_sum / n_eq, 1.0 / m)).epsilon(2e-15));
    }
  }
  // With m = 3 and n_eq = 1 the value is 7.65… by hand: (13.5 + 96 + 108 + 512 + 364.5)^{1/3} = 1094^{1/3}.
  CHECK(damage_equivalent_load(cycles, 1.0, FatigueParams{3.0, std::nullopt, 0.0, 1.0}) == Approx(std::cbrt(1094.0)).epsilon(2e-15));  // measured 1.7e-16
}

TEST_CASE("DEL of a pure sine is 2A (f T / n_eq)^(1/m)", "[verification]") {
  // Closed form: f T cycles of range 2A (see sampled_cosine), DEL = 2A (f T / (f_eq T))^{1/m}.
  const double amplitude = 3.0, frequency_hz = 0.25;
  const int periods = 150;
  const double duration_s = periods / frequency_hz;  // 600 s
  const std::vector<RainflowCycle> cycles = rainflow_cycles(sampled_cosine(amplitude, 0.0, periods));
  for (const double m : {3.0, 10.0})
    for (const double f_eq : {1.0, 0.1}) {
      const double expected = 2.0 * amplitude * std::pow(frequency_hz * duration_s / (f_eq * duration_s), 1.0 / m);
      // 2e-15: 150 equal terms summed, pow (measured ≤ 1.7e-16 relative).
      CHECK(damage_equivalent_load(cycles, duration_s, FatigueParams{m, std::nullopt, 0.0, f_eq}) == Approx(expected).epsilon(2e-15));
    }
}

TEST_CASE("Goodman-corrected DEL of a sine with a mean has its closed form", "[verification]") {
  // Every cycle has mean μ: L_RF = 2A (L_ult − |L_MF|)/(L_ult − |μ|) (MLife, Goodman exponent 1), so
  // DEL = 2A (L_ult − |L_MF|)/(L_ult − |μ|) · (f T / n_eq)^{1/m}.
  const double amplitude = 2.0, mean = -30.0, ultimate = 100.0, frequency_hz = 0.5, m = 10.0;
  const int periods = 100;
  const double duration_s = periods / frequency_hz;
  const std::vector<RainflowCycle> cycles = rainflow_cycles(sampled_cosine(amplitude, mean, periods));
  for (const double fixed_mean : {0.0, 20.0}) {
    const double expected =
        2.0 * amplitude * (ultimate - std::abs(fixed_mean)) / (ultimate - std::abs(mean)) * std::pow(frequency_hz, 1.0 / m);
    // 2e-15: cycle means (μ + A + μ − A)/2 and the ratio carry round-off (measured ≤ 1.7e-16).
    CHECK(damage_equivalent_load(cycles, duration_s, FatigueParams{m, ultimate, fixed_mean, 1.0}) == Approx(expected).epsilon(2e-15));
  }
}

TEST_CASE("the Goodman correction refuses a mean at the ultimate load", "[unit]") {
  const RainflowCycle cycle{1.0, 50.0, 1.0};
  CHECK(fatigue_range(cycle, FatigueParams{3.0, std::nullopt, 0.0, 1.0}) == 1.0);
  CHECK(fatigue_range(cycle, FatigueParams{3.0, 100.0, 0.0, 1.0}) == 2.0);  // 1 · 100/(100 − 50)
  CHECK_THROWS_AS(fatigue_range(cycle, FatigueParams{3.0, 50.0, 0.0, 1.0}), fowtsim::InputError);
  CHECK_THROWS_AS(fatigue_range(RainflowCycle{1.0, 0.0, 1.0}, FatigueParams{3.0, 10.0, -10.0, 1.0}), fowtsim::InputError);
}

TEST_CASE("residue counting changes the DEL of the ASTM example as the counts say", "[unit]") {
  // Full residue: the residue ranges 3, 4, 8, 9, 8, 6 count 1.0 each, the closed cycle 4 stays 1.0.
  const std::vector<double> series{-2, 1, -3, 5, -1, 3, -4, 4, -2};
  const double m = 4.0;
  const double hand_sum = std::pow(4, m) + std::pow(3, m) + std::pow(4, m) + 2 * std::pow(8, m) + std::pow(9, m) + std::pow(6, m);
  const FatigueParams params{m, std::nullopt, 0.0, 1.0};
  CHECK(damage_sum(rainflow_cycles(series, ResidueCounting::full_cycles), params) == hand_sum);  // integers, exact
}
