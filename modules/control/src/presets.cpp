#include "fowtsim/control/presets.hpp"

namespace fowtsim::control {

BaselineParams nrel5mw_land_baseline() {
  BaselineParams p;  // the defaults of BaselineParams are the land-based constants of 38060 Ch. 7
  p.sample_time_s = 0.000125;
  p.filter_corner_rad_s = 1.570796;
  p.cut_in_speed_rad_s = 70.16224;
  p.region2_start_speed_rad_s = 91.21091;
  p.region2_gain_N_m_s2 = 2.332287;
  p.rated_generator_speed_rad_s = 121.6805;
  p.rated_power_W = 5296610.0;
  p.slip_percent = 10.0;
  p.max_torque_N_m = 47402.91;
  p.max_torque_rate_N_m_s = 15000.0;
  p.region3_min_pitch_rad = 0.01745329;
  p.region3_torque = Region3Torque::constant_power;
  p.reference_speed_rad_s = 122.9096;
  p.proportional_gain_s = 0.01882681;
  p.integral_gain = 0.008068634;
  p.gain_schedule_pitch_rad = 0.1099965;
  p.min_pitch_rad = 0.0;
  p.max_pitch_rad = 1.570796;
  p.max_pitch_rate_rad_s = 0.1396263;
  p.generator_efficiency = 0.944;
  return p;
}

BaselineParams oc3_hywind_baseline() {
  BaselineParams p = nrel5mw_land_baseline();
  p.sample_time_s = 0.00125;
  p.proportional_gain_s = 0.006275604;
  p.integral_gain = 0.0008965149;
  p.region3_torque = Region3Torque::constant_torque;
  return p;
}

std::optional<BaselineParams> baseline_preset(std::string_view name) {
  if (name == "nrel5mw_land") return nrel5mw_land_baseline();
  if (name == "oc3_hywind") return oc3_hywind_baseline();
  return std::nullopt;
}

}  // namespace fowtsim::control
