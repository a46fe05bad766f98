#include "fowtsim/post/damage_equivalent_load.hpp"

#include <cmath>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::post {

double fatigue_range(const RainflowCycle& cycle, const FatigueParams& params) {
  if (!params.ultimate_load) return cycle.range;
  const double ultimate = *params.ultimate_load;
  if (std::abs(cycle.mean) >= ultimate || std::abs(params.goodman_fixed_mean) >= ultimate)
    throw InputError({"post.del", std::nullopt, "ultimate_load", "the ultimate load must exceed every cycle mean"},
                     fmt::format("Goodman correction: a cycle mean of {:.6g} or the fixed mean {:.6g} reaches the "
                                 "ultimate load {:.6g}",
                                 cycle.mean, params.goodman_fixed_mean, ultimate));
  return cycle.range * (ultimate - std::abs(params.goodman_fixed_mean)) / (ultimate - std::abs(cycle.mean));
}

double damage_sum(std::span<const RainflowCycle> cycles, const FatigueParams& params) {
  double sum = 0.0;
  for (const RainflowCycle& cycle : cycles) sum += cycle.count * std::pow(fatigue_range(cycle, params), params.wohler_exponent);
  return sum;
}

double damage_equivalent_load(std::span<const RainflowCycle> cycles, double duration_s, const FatigueParams& params) {
  if (!(duration_s > 0.0) || !(params.wohler_exponent > 0.0) || !(params.equivalent_frequency_hz > 0.0))
    throw Error({"post.del", std::nullopt, "", ""},
                fmt::format("damage_equivalent_load: duration_s = {}, wohler_exponent = {} and equivalent_frequency_hz "
                            "= {} must all be > 0",
                            duration_s, params.wohler_exponent, params.equivalent_frequency_hz));
  const double equivalent_cycles = params.equivalent_frequency_hz * duration_s;
  return std::pow(damage_sum(cycles, params) / equivalent_cycles, 1.0 / params.wohler_exponent);
}

}  // namespace fowtsim::post
