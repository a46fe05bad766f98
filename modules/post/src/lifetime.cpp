#include "fowtsim/post/lifetime.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::post {

WindSpeedDistribution WindSpeedDistribution::weibull(double shape_k, double scale_m_s) {
  if (!(shape_k > 0.0) || !(scale_m_s > 0.0))
    throw InputError({"post.lifetime", std::nullopt, "distribution", ""},
                     fmt::format("Weibull shape k = {} and scale A = {} m/s must be > 0", shape_k, scale_m_s));
  return {shape_k, scale_m_s};
}

WindSpeedDistribution WindSpeedDistribution::weibull_with_mean(double shape_k, double mean_speed_m_s) {
  if (!(shape_k > 0.0)) return weibull(shape_k, 1.0);  // reports the bad shape
  return weibull(shape_k, mean_speed_m_s / std::tgamma(1.0 + 1.0 / shape_k));
}

WindSpeedDistribution WindSpeedDistribution::rayleigh(double mean_speed_m_s) {
  return weibull(2.0, 2.0 * mean_speed_m_s / std::sqrt(std::numbers::pi));
}

double WindSpeedDistribution::cumulative_probability(double speed_m_s) const {
  if (speed_m_s <= 0.0) return 0.0;
  return -std::expm1(-std::pow(speed_m_s / scale_m_s, shape_k));
}

double WindSpeedDistribution::mean_speed_m_s() const { return scale_m_s * std::tgamma(1.0 + 1.0 / shape_k); }

double iec_class_mean_speed_m_s(int wind_turbine_class) {
  switch (wind_turbine_class) {
    case 1: return 10.0;
    case 2: return 8.5;
    case 3: return 7.5;
    default:
      throw InputError({"post.lifetime", std::nullopt, "iec_class", "1, 2 or 3"},
                       fmt::format("IEC 61400-1 wind turbine class {} does not exist", wind_turbine_class));
  }
}

std::vector<double> run_time_fractions(std::span<const double> wind_speeds_m_s, const WindSpeedDistribution& distribution,
                                       double bin_width_m_s, bool renormalise) {
  if (!(bin_width_m_s > 0.0))
    throw InputError({"post.lifetime", std::nullopt, "bin_width_m_s", ""}, fmt::format("bin width {} m/s must be > 0", bin_width_m_s));
  std::vector<double> speeds(wind_speeds_m_s.begin(), wind_speeds_m_s.end());
  std::sort(speeds.begin(), speeds.end());
  speeds.erase(std::unique(speeds.begin(), speeds.end()), speeds.end());
  const double half = 0.5 * bin_width_m_s;
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    if (speeds[i] - half < 0.0)
      throw InputError({"post.lifetime", std::nullopt, "wind_speed_m_s", "narrow the bins"},
                       fmt::format("the bin of {} m/s reaches below 0 m/s with a width of {} m/s", speeds[i], bin_width_m_s));
    if (i > 0 && speeds[i] - speeds[i - 1] < bin_width_m_s * (1.0 - 1e-12))
      throw InputError({"post.lifetime", std::nullopt, "wind_speed_m_s", "narrow the bins or merge the speeds"},
                       fmt::format("runs at {} and {} m/s are closer than the bin width {} m/s: their bins overlap",
                                   speeds[i - 1], speeds[i], bin_width_m_s));
  }
  std::vector<double> fractions;
  fractions.reserve(wind_speeds_m_s.size());
  for (const double v : wind_speeds_m_s) {
    const auto runs_in_bin = std::count(wind_speeds_m_s.begin(), wind_speeds_m_s.end(), v);
    const double bin_probability = distribution.cumulative_probability(v + half) - distribution.cumulative_probability(v - half);
    fractions.push_back(bin_probability / static_cast<double>(runs_in_bin));
  }
  if (renormalise) {
    double total = 0.0;
    for (const double f : fractions) total += f;
    if (total > 0.0)
      for (double& f : fractions) f /= total;
  }
  return fractions;
}

LifetimeLoad lifetime_damage_equivalent_load(std::span<const LifetimeRun> runs, double wohler_exponent, double design_life_s,
                                             double equivalent_frequency_hz) {
  if (!(wohler_exponent > 0.0) || !(design_life_s > 0.0) || !(equivalent_frequency_hz > 0.0))
    throw Error({"post.lifetime", std::nullopt, "", ""},
                fmt::format("lifetime_damage_equivalent_load: wohler_exponent = {}, design_life_s = {} and "
                            "equivalent_frequency_hz = {} must be > 0",
                            wohler_exponent, design_life_s, equivalent_frequency_hz));
  LifetimeLoad load;
  for (const LifetimeRun& run : runs) {
    if (!(run.duration_s > 0.0))
      throw Error({"post.lifetime", std::nullopt, "duration_s", ""}, fmt::format("a run's duration_s = {} must be > 0", run.duration_s));
    load.damage_sum += run.time_fraction * (design_life_s / run.duration_s) * run.damage_sum;
  }
  load.damage_equivalent_load = std::pow(load.damage_sum / (equivalent_frequency_hz * design_life_s), 1.0 / wohler_exponent);
  return load;
}

}  // namespace fowtsim::post
