#include "fowtsim/flexbody/hub_spin.hpp"

#include <cmath>
#include <numbers>
#include <optional>

#include "fowtsim/core/error.hpp"

namespace fowtsim::flexbody {

HubSpin kane_spin_up(double final_rate, double spin_up_time) {
  if (!(spin_up_time > 0.0))
    throw InputError({"flexbody", std::nullopt, "spin-up time", "give T_s > 0"},
                     "Kane's spin-up needs a positive spin-up time");
  const double slope = final_rate / spin_up_time, w = 2.0 * std::numbers::pi / spin_up_time;
  return {[=](double t) {
            if (t <= 0.0) return 0.0;
            if (t >= spin_up_time) return final_rate;
            return slope * (t - std::sin(w * t) / w);
          },
          [=](double t) {
            if (t < 0.0 || t >= spin_up_time) return 0.0;
            return slope * (1.0 - std::cos(w * t));
          }};
}

}  // namespace fowtsim::flexbody
