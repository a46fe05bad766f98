#include "fowtsim/wind/iec_events.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "fowtsim/core/error.hpp"
#include "fowtsim/wind/iec_conditions.hpp"

namespace fowtsim::wind {
namespace {

constexpr double kPi = std::numbers::pi;
// IEC 61400-1 ed. 3 §6.3.2.2–6.3.2.6 (ed. 4 §6.3.3.3–6.3.3.7, the same values).
constexpr double kEogPeriod_s = 10.5;  // EOG T
constexpr double kEdcPeriod_s = 6.0;   // EDC T
constexpr double kEcdPeriod_s = 10.0;  // ECD T
constexpr double kEwsPeriod_s = 12.0;  // EWS T
constexpr double kEcdGust_m_s = 15.0;  // ECD V_cg
constexpr double kEwsBeta = 6.4;       // EWS β (eqs. 26–27)

[[noreturn]] void bad(const std::string& key, const std::string& message) {
  throw InputError({"wind", std::nullopt, "wind." + key, ""}, "wind." + key + ": " + message);
}

double rotor_size_factor(double rotor_diameter_m, double hub_height_m) {
  return 1.0 + 0.1 * rotor_diameter_m / turbulence_scale_parameter(hub_height_m);
}

}  // namespace

double eog_gust_speed(double v_hub, double d, double z_hub, int iec_wind_class, TurbulenceCategory category) {
  const double v_e1 = ewm_steady_1yr_speed(iec_wind_class);
  return std::min(1.35 * (v_e1 - v_hub), 3.3 * ntm_sigma(category, v_hub) / rotor_size_factor(d, z_hub));
}

double edc_direction_change(double v_hub, double d, double z_hub, TurbulenceCategory category) {
  const double theta = 4.0 * std::atan(ntm_sigma(category, v_hub) / (v_hub * rotor_size_factor(d, z_hub)));
  return std::min(theta, kPi);  // §6.3.2.4: θ_e limited to ±180°
}

double ecd_direction_change(double v_hub) { return v_hub < 4.0 ? kPi : (720.0 / v_hub) * kPi / 180.0; }

double ews_shear_speed(double v_hub, double d, double z_hub, TurbulenceCategory category) {
  return 2.5 + 0.2 * kEwsBeta * ntm_sigma(category, v_hub) * std::pow(d / turbulence_scale_parameter(z_hub), 0.25);
}

WindEvent make_wind_event(const WindParams& p) {
  const WindEventParams& e = p.event;
  WindEvent w;
  w.type = e.type;
  if (e.type == WindEventType::none) return w;
  if (!(std::isfinite(e.start_s) && e.start_s >= 0.0)) bad("event.start_s", "expected a time >= 0 s, found " + std::to_string(e.start_s));
  if (e.sign != 1 && e.sign != -1) bad("event.sign", "expected 1 or -1, found " + std::to_string(e.sign));
  if (!(std::isfinite(e.rotor_diameter_m) && e.rotor_diameter_m > 0.0))
    bad("event.rotor_diameter_m", "expected the rotor diameter D > 0 m (required when wind.event.type is not none)");
  if (e.iec_wind_class < 1 || e.iec_wind_class > 3) bad("event.iec_wind_class", "expected 1, 2 or 3");
  if (p.model == WindModel::uniform_file)
    bad("event.type", "an IEC event cannot be superposed on a uniform wind file: write the event into the file");
  const double v_hub = p.speed_m_s, z_hub = p.reference_height_m, d = e.rotor_diameter_m, s = e.sign;
  if (!(v_hub > 0.0)) bad("speed_m_s", "expected a hub speed V_hub > 0 m/s for a wind event");
  w.start_s = e.start_s;
  w.rotor_diameter_m = d;
  switch (e.type) {
    case WindEventType::EOG:
      w.duration_s = kEogPeriod_s;
      w.gust_m_s = eog_gust_speed(v_hub, d, z_hub, e.iec_wind_class, e.turbulence_class);
      if (!(w.gust_m_s > 0.0))
        bad("speed_m_s", "the EOG needs V_hub below V_e1 = " + std::to_string(ewm_steady_1yr_speed(e.iec_wind_class)) +
                             " m/s (0.8 · 1.4 V_ref), found " + std::to_string(v_hub) + " m/s");
      break;
    case WindEventType::EDC:
      w.duration_s = kEdcPeriod_s;
      w.direction_change_rad = s * edc_direction_change(v_hub, d, z_hub, e.turbulence_class);
      break;
    case WindEventType::ECD:
      if (v_hub > reference_wind_speed(e.iec_wind_class))
        bad("speed_m_s", "the ECD is defined up to V_ref = " + std::to_string(reference_wind_speed(e.iec_wind_class)) +
                             " m/s, found " + std::to_string(v_hub) + " m/s");
      w.duration_s = kEcdPeriod_s;
      w.gust_m_s = kEcdGust_m_s;
      w.direction_change_rad = s * ecd_direction_change(v_hub);
      break;
    case WindEventType::EWS_vertical:
    case WindEventType::EWS_horizontal:
      w.duration_s = kEwsPeriod_s;
      w.shear_m_s = s * ews_shear_speed(v_hub, d, z_hub, e.turbulence_class);
      break;
    case WindEventType::none: break;
  }
  return w;
}

WindEventValue wind_event_at(const WindEvent& w, double t) {
  WindEventValue v;
  if (w.type == WindEventType::none) return v;
  const double tau = t - w.start_s, T = w.duration_s;
  if (tau < 0.0) return v;
  const bool during = tau <= T;
  switch (w.type) {
    case WindEventType::EOG:
      if (during) v.speed_m_s = -0.37 * w.gust_m_s * std::sin(3.0 * kPi * tau / T) * (1.0 - std::cos(2.0 * kPi * tau / T));
      break;
    case WindEventType::EDC:
      v.direction_rad = during ? 0.5 * w.direction_change_rad * (1.0 - std::cos(kPi * tau / T)) : w.direction_change_rad;
      break;
    case WindEventType::ECD: {
      const double ramp = during ? 0.5 * (1.0 - std::cos(kPi * tau / T)) : 1.0;
      v.speed_m_s = w.gust_m_s * ramp;
      v.direction_rad = w.direction_change_rad * ramp;
      break;
    }
    case WindEventType::EWS_vertical:
    case WindEventType::EWS_horizontal: {
      if (!during) break;
      const double rate = w.shear_m_s / w.rotor_diameter_m * (1.0 - std::cos(2.0 * kPi * tau / T));
      (w.type == WindEventType::EWS_vertical ? v.vertical_shear_per_s : v.horizontal_shear_per_s) = rate;
      break;
    }
    case WindEventType::none: break;
  }
  return v;
}

}  // namespace fowtsim::wind
