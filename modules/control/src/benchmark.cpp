#include "fowtsim/control/benchmark.hpp"

#include <chrono>
#include <cmath>
#include <type_traits>

#include "fowtsim/control/baseline_controller.hpp"
#include "fowtsim/control/external_controller.hpp"
#include "fowtsim/control/presets.hpp"

namespace fowtsim::control {
namespace {

constexpr double kStep = 0.0125;  // OC3 deck's large step [s]

// Generator speed sweeping 100…130 rad/s with a 20 s period: regions 2, 2½ and 3.
ControllerInput input_at(int k, const ControllerOutput& last) {
  ControllerInput u;
  u.generator_speed_rad_s = 115.0 + 15.0 * std::sin(2.0 * 3.141592653589793 * k * kStep / 20.0);
  u.rotor_speed_rad_s = u.generator_speed_rad_s / 97.0;
  u.blade_pitch_rad = last.blade_pitch_rad;  // ideal actuator
  u.hub_wind_speed_m_s = 12.0;
  return u;
}

template <class Controller>
ControlBenchRow time_calls(const std::string& name, const typename Controller::Params& p, int calls) {
  typename Controller::State s = Controller::make_state(p);
  ControllerOutput y;
  double sink = 0.0;
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < calls; ++k) {
    const ControllerInput u = input_at(k, y);
    Controller::advance(p, u, k * kStep, kStep, s);
    y = Controller::outputs(p, u, s);
    sink += y.generator_torque_N_m;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if constexpr (std::is_same_v<Controller, ExternalController>) Controller::finish(p, calls * kStep, s);
  if (!std::isfinite(sink)) return {name + " (non-finite result)", calls, 0.0};
  return {name, calls, 1e9 * seconds / calls};
}

}  // namespace

std::vector<ControlBenchRow> bench_control(const std::string& discon_library_path, int calls) {
  std::vector<ControlBenchRow> rows;
  rows.push_back(time_calls<BaselineController>("built-in, NREL 5MW land", nrel5mw_land_baseline(), calls));
  rows.push_back(time_calls<BaselineController>("built-in, OC3-Hywind", oc3_hywind_baseline(), calls));
  if (!discon_library_path.empty()) {
    ExternalSettings e;
    e.library_path = discon_library_path;
    e.infile = "oc3_hywind";
    const ExternalController::Params p = ExternalController::make_params(e);
    rows.push_back(time_calls<ExternalController>("DISCON library, OC3-Hywind", p, calls));
  }
  return rows;
}

}  // namespace fowtsim::control
