#include "sweep/trim.hpp"

#include <algorithm>
#include <numeric>
#include <set>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/post/statistics.hpp"

namespace fowtsim::driver::sweep {

namespace {

std::string number_text(double value) { return fmt::format("{}", value); }

std::optional<std::string> override_of(const SweepCase& c, const std::string& key) {
  for (auto it = c.overrides.rbegin(); it != c.overrides.rend(); ++it)
    if (it->key_path == key) return it->yaml_value;
  return std::nullopt;
}

std::string trim_name(double speed_m_s) {
  std::string piece = number_text(speed_m_s);
  return "trim_ws" + piece;
}

}  // namespace

bool is_trimmed(const SweepCase& c) {
  if (!c.wind_speed_m_s) return false;
  const std::optional<std::string> mode = override_of(c, "controller.operating_mode");
  if (mode && *mode != "operating") return false;
  const std::optional<std::string> spin = override_of(c, "structure.degrees_of_freedom.rotor_speed");
  return !(spin && *spin == "held");
}

std::vector<SweepCase> trim_cases(const SweepSpec& spec, const std::vector<SweepCase>& cases) {
  std::set<double> speeds;
  for (const SweepCase& c : cases)
    if (is_trimmed(c)) speeds.insert(*c.wind_speed_m_s);
  std::vector<SweepCase> runs;
  for (const double v : speeds) {
    SweepCase t;
    t.name = trim_name(v);
    t.wind_speed_m_s = v;
    auto set = [&](const char* key, std::string value) { t.overrides.push_back({key, std::move(value), {}, false}); };
    set("simulation.t_max_s", number_text(spec.trim->duration_s));
    // Steady wind at the speed, the deck's own shear exponent; no waves: the mean operating point.
    set("wind.model", "power_law");
    set("wind.speed_m_s", number_text(v));
    set("wind.reference_height_m", number_text(spec.turbine.hub_height_m));
    set("waves.model", "still");
    runs.push_back(std::move(t));
  }
  return runs;
}

SweepLayout trim_layout(const SweepLayout& layout) { return SweepLayout{layout.root / "trim"}; }

OperatingPoint read_operating_point(const std::filesystem::path& output, const TrimSpec& trim) {
  const io::ChannelTable table = io::read_hdf5_channels(output);
  const double end = table.time().back();
  const post::RowRange window = post::rows_in_window(table.time(), post::TimeWindow{end - trim.average_s, end});
  auto mean = [&](const char* name) -> std::optional<double> {
    const std::optional<std::size_t> c = table.find(name);
    if (!c) return std::nullopt;
    const auto first = table.columns[*c].begin() + static_cast<std::ptrdiff_t>(window.first);
    return std::accumulate(first, first + static_cast<std::ptrdiff_t>(window.size()), 0.0) / static_cast<double>(window.size());
  };
  auto required = [&](const char* name) {
    const std::optional<double> v = mean(name);
    if (!v)
      throw Error({"sweep", std::nullopt, "trim", "keep the channel in the base deck's output.channels"},
                  fmt::format("the trim run {} has no channel {}", output.string(), name));
    return *v;
  };
  OperatingPoint p;
  p.rotor_speed_rpm = required("RotSpeed");
  p.blade_pitch_deg = required("BldPitch1");
  const char* position[] = {"PtfmSurge", "PtfmSway", "PtfmHeave"};
  const char* angles[] = {"PtfmRoll", "PtfmPitch", "PtfmYaw"};
  for (int i = 0; i < 3; ++i) {
    p.platform_position_m[i] = required(position[i]);
    p.platform_angles_deg[i] = required(angles[i]);
  }
  const std::optional<double> fa = mean("TTDspFA"), ss = mean("TTDspSS");
  if (fa && ss) p.tower_top_deflection_m = std::array<double, 2>{*fa, *ss};
  return p;
}

void apply_trim(std::vector<SweepCase>& cases, const std::map<double, OperatingPoint>& points, bool settle_rayleigh_ritz_blades) {
  auto triple = [](const auto& v, std::size_t n) {
    std::string text = "[";
    for (std::size_t i = 0; i < n; ++i) text += (i ? ", " : "") + number_text(v[i]);
    return text + "]";
  };
  for (SweepCase& c : cases) {
    if (!is_trimmed(c)) continue;
    const auto it = points.find(*c.wind_speed_m_s);
    if (it == points.end()) continue;
    const OperatingPoint& p = it->second;
    std::vector<DeckOverride> keys = {
        {"structure.initial_conditions.rotor_speed_rpm", number_text(p.rotor_speed_rpm), {}, false},
        {"structure.initial_conditions.blade_pitch_deg", number_text(p.blade_pitch_deg), {}, false},
        {"structure.initial_conditions.platform_position_m", triple(p.platform_position_m, 3), {}, true},
        {"structure.initial_conditions.platform_angles_deg", triple(p.platform_angles_deg, 3), {}, true},
    };
    // Rayleigh–Ritz blades at their static deflection under this operating point (MBBT blades
    // start from theirs by blades.start).
    if (settle_rayleigh_ritz_blades) keys.push_back({"structure.initial_conditions.blade_deflection", "static", {}, false});
    if (p.tower_top_deflection_m)
      keys.push_back({"structure.initial_conditions.tower_top_deflection_m", triple(*p.tower_top_deflection_m, 2), {}, true});
    // First, so that any key the presets or the spec set over them wins.
    c.overrides.insert(c.overrides.begin(), keys.begin(), keys.end());
  }
}

}  // namespace fowtsim::driver::sweep
