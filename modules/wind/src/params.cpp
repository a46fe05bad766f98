#include "fowtsim/wind/params.hpp"

#include <cmath>
#include <string>

#include "fowtsim/core/error.hpp"
#include "fowtsim/wind/iec_conditions.hpp"
#include "fowtsim/wind/iec_events.hpp"

namespace fowtsim::wind {
namespace {

[[noreturn]] void bad(const std::string& key, const std::string& expected, double found) {
  throw InputError(ErrorContext{"wind", std::nullopt, "wind." + key, ""},
                   "wind." + key + ": expected " + expected + ", found " + std::to_string(found));
}

void require(bool ok, const std::string& key, const std::string& expected, double found) {
  if (!ok) bad(key, expected, found);
}

[[noreturn]] void bad_choice(const std::string& key, const std::string& text, const std::string& choices) {
  throw InputError(ErrorContext{"wind", std::nullopt, "wind." + key, ""},
                   "wind." + key + ": expected one of " + choices + ", found '" + text + "'");
}

void validate_turbulence(const TurbulenceParams& t, double speed_m_s, double hub_m) {
  const std::string k = "turbulence.";
  require(t.iec_wind_class >= 1 && t.iec_wind_class <= 3, k + "iec_wind_class", "1, 2 or 3", t.iec_wind_class);
  require(t.ny >= 2 && t.ny <= 1024, k + "ny", "an integer in [2, 1024]", t.ny);
  require(t.nz >= 2 && t.nz <= 1024, k + "nz", "an integer in [2, 1024]", t.nz);
  require(t.width_m > 0.0 && std::isfinite(t.width_m), k + "width_m", "a positive width [m]", t.width_m);
  require(t.height_m > 0.0 && std::isfinite(t.height_m), k + "height_m", "a positive height [m]", t.height_m);
  require(t.height_m < 2.0 * hub_m, k + "height_m",
          "less than twice reference_height_m (the grid, centred on the hub, must stay above SWL)", t.height_m);
  require(t.dt_s > 0.0 && std::isfinite(t.dt_s), k + "dt_s", "a positive time step [s]", t.dt_s);
  require(t.duration_s >= 4.0 * t.dt_s && std::isfinite(t.duration_s), k + "duration_s",
          "at least 4 time steps [s]", t.duration_s);
  require(t.duration_s / t.dt_s <= 1e7, k + "duration_s", "at most 1e7 time steps", t.duration_s / t.dt_s);
  if (t.model == TurbulenceModel::ETM) {
    // IEC eq. 19 is defined where it gives a positive sigma (low speeds can make it negative).
    require(etm_sigma(t.category, t.iec_wind_class, speed_m_s) > 0.0, "speed_m_s",
            "a hub speed giving a positive ETM standard deviation", speed_m_s);
  }
}

}  // namespace

void validate(const WindParams& p) {
  require(std::isfinite(p.speed_m_s) && p.speed_m_s >= 0.0 && p.speed_m_s <= 100.0, "speed_m_s",
          "a speed in [0, 100] m/s", p.speed_m_s);
  require(std::isfinite(p.reference_height_m) && p.reference_height_m > 0.0, "reference_height_m",
          "a positive height above SWL [m]", p.reference_height_m);
  require(std::isfinite(p.shear_exponent) && p.shear_exponent >= -1.0 && p.shear_exponent <= 2.0,
          "shear_exponent", "a power-law exponent in [-1, 2]", p.shear_exponent);
  require(std::isfinite(p.roughness_m) && p.roughness_m > 0.0 && p.roughness_m < p.reference_height_m,
          "roughness_m", "a roughness length in (0, reference_height_m) [m]", p.roughness_m);
  require(std::isfinite(p.direction_deg) && std::abs(p.direction_deg) <= 360.0, "direction_deg",
          "an angle in [-360, 360] deg", p.direction_deg);
  require(std::isfinite(p.upflow_deg) && std::abs(p.upflow_deg) <= 45.0, "upflow_deg",
          "an angle in [-45, 45] deg", p.upflow_deg);
  require(p.probe_point_m.allFinite(), "probe_point_m", "finite coordinates [m]", p.probe_point_m.norm());
  if (p.model == WindModel::bts && p.file.empty())
    throw InputError(ErrorContext{"wind", std::nullopt, "wind.file", ""},
                     "wind.file: expected the path of a TurbSim .bts file for model bts");
  if (p.model == WindModel::turbulent) {
    require(p.speed_m_s > 0.0, "speed_m_s", "a positive hub speed for model turbulent", p.speed_m_s);
    validate_turbulence(p.turbulence, p.speed_m_s, p.reference_height_m);
  }
  if (p.model == WindModel::uniform_file) {
    if (p.uniform.rows.empty())
      throw InputError(ErrorContext{"wind", std::nullopt, "wind.file", ""},
                       "wind.file: expected an OpenFAST uniform wind file (.hh) with data rows for model uniform_file");
    require(std::isfinite(p.reference_length_m) && p.reference_length_m > 0.0, "reference_length_m",
            "a positive reference length [m] of the file's linear shears for model uniform_file (InflowWind RefLength, "
            "usually the rotor diameter)",
            p.reference_length_m);
  }
  make_wind_event(p);  // the event's own checks (rotor diameter, sign, its speed range)
}

WindModel parse_wind_model(const std::string& text) {
  if (text == "steady") return WindModel::steady;
  if (text == "power_law") return WindModel::power_law;
  if (text == "log") return WindModel::log;
  if (text == "bts") return WindModel::bts;
  if (text == "turbulent") return WindModel::turbulent;
  if (text == "uniform_file") return WindModel::uniform_file;
  bad_choice("model", text, "steady, power_law, log, bts, turbulent, uniform_file");
}

TurbulenceCategory parse_turbulence_category(const std::string& text) {
  if (text == "A") return TurbulenceCategory::A;
  if (text == "B") return TurbulenceCategory::B;
  if (text == "C") return TurbulenceCategory::C;
  bad_choice("turbulence.class", text, "A, B, C");
}

TurbulenceModel parse_turbulence_model(const std::string& text) {
  if (text == "NTM") return TurbulenceModel::NTM;
  if (text == "ETM") return TurbulenceModel::ETM;
  if (text == "EWM") return TurbulenceModel::EWM;
  bad_choice("turbulence.model", text, "NTM, ETM, EWM");
}

WindEventType parse_wind_event_type(const std::string& text) {
  if (text == "none") return WindEventType::none;
  if (text == "EOG") return WindEventType::EOG;
  if (text == "EDC") return WindEventType::EDC;
  if (text == "ECD") return WindEventType::ECD;
  if (text == "EWS_vertical") return WindEventType::EWS_vertical;
  if (text == "EWS_horizontal") return WindEventType::EWS_horizontal;
  bad_choice("event.type", text, "none, EOG, EDC, ECD, EWS_vertical, EWS_horizontal");
}

}  // namespace fowtsim::wind
