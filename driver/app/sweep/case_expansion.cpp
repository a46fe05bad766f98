#include "sweep/case_expansion.hpp"

#include <algorithm>
#include <cmath>
#include <cctype>
#include <charconv>
#include <set>

#include <fmt/format.h>

#include "sweep/iec_presets.hpp"

namespace fowtsim::driver::sweep {

std::uint64_t case_seed(const std::string& canonical_case, const std::string& stream) {
  return io::fnv1a_64(canonical_case + "|" + stream) % (std::uint64_t{1} << 31);
}

namespace {

// Whether a factor's key changes the turbulent field itself (its seed, spectrum, grid or mean
// profile); the wind direction, upflow and the deterministic events act on how the field is used.
bool shapes_turbulence(const std::string& key_path) {
  return key_path.starts_with("wind.") && key_path != "wind.direction_deg" && key_path != "wind.upflow_deg" &&
         !key_path.starts_with("wind.event.");
}

const io::DeckNode* find_path(const io::DeckNode& root, std::initializer_list<const char*> keys) {
  const io::DeckNode* node = &root;
  for (const char* key : keys) {
    node = node->find(key);
    if (node == nullptr) return nullptr;
  }
  return node;
}

std::optional<double> parse_number(const std::string& text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::optional<std::uint64_t> parse_seed(const std::string& text) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// Shortest text that reads back as the same double ("12", "12.5", "-8"): names and decks agree.
std::string number_text(double value) { return fmt::format("{}", value); }

// A factor value inside a file name: letters, digits and . + - kept, anything else becomes _.
std::string name_piece(const std::string& text) {
  std::string piece = text;
  for (char& c : piece)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '+' && c != '-') c = '_';
  return piece;
}

// One varied quantity of a group: per value, its name piece and the deck keys it sets.
struct Axis {
  std::string label;                         // name piece prefix ("ws", "yaw", "wh", a preset's, or a key's last part)
  std::vector<std::string> names;            // name piece per value
  std::vector<std::vector<PresetKey>> keys;  // deck keys per value
  io::SourceLocation source;                 // where the values are written in the spec
  bool from_set = false;                     // a `set` key: applied again last
  std::size_t size() const { return names.size(); }
};

Axis key_axis(const std::string& label, const std::string& key, const std::vector<std::string>& values, io::SourceLocation source,
              bool from_set = false) {
  Axis axis{label, {}, {}, std::move(source), from_set};
  for (const std::string& v : values) {
    axis.names.push_back(v);
    axis.keys.push_back({{key, v}});
  }
  return axis;
}

// Index of each axis per factor combination, the first axis outermost.
std::vector<std::vector<std::size_t>> combinations(const std::vector<Axis>& axes, Combination combine) {
  std::vector<std::vector<std::size_t>> result;
  if (combine == Combination::zip) {
    std::size_t length = 1;
    for (const Axis& a : axes) length = std::max(length, a.size());
    for (std::size_t i = 0; i < length; ++i) {
      std::vector<std::size_t> index;
      for (const Axis& a : axes) index.push_back(a.size() == 1 ? 0 : i);
      result.push_back(std::move(index));
    }
    return result;
  }
  std::vector<std::size_t> index(axes.size(), 0);
  while (true) {
    result.push_back(index);
    std::size_t k = axes.size();
    while (k > 0 && ++index[k - 1] == axes[k - 1].size()) index[--k] = 0;
    if (k == 0) return result;
  }
}

std::vector<Axis> group_axes(const LoadCaseGroup& g, const PresetPlan& plan) {
  auto numbers = [](const std::vector<double>& v) {
    std::vector<std::string> text;
    for (const double x : v) text.push_back(number_text(x));
    return text;
  };
  std::vector<Axis> axes;
  const std::vector<double>& speeds = g.wind_speeds_m_s.empty() ? plan.wind_speeds_m_s : g.wind_speeds_m_s;
  if (!speeds.empty()) axes.push_back(key_axis("ws", "wind.speed_m_s", numbers(speeds), g.location));
  for (const PresetFactor& f : plan.factors) {
    if (f.label == "yaw" && !g.yaw_misalignment_deg.empty()) continue;  // the spec's own yaw list replaces the preset's
    axes.push_back({f.label, f.names, f.keys, g.location, false});
  }
  if (!g.yaw_misalignment_deg.empty()) axes.push_back(key_axis("yaw", "wind.direction_deg", numbers(g.yaw_misalignment_deg), g.location));
  if (!g.wave_heading_deg.empty()) axes.push_back(key_axis("wh", "waves.heading_deg", numbers(g.wave_heading_deg), g.location));
  for (const KeyFactor& f : g.set) {
    const std::size_t dot = f.key_path.rfind('.');
    axes.push_back(key_axis(dot == std::string::npos ? f.key_path : f.key_path.substr(dot + 1), f.key_path, f.values, f.location, true));
  }
  return axes;
}

class CaseBuilder {
 public:
  explicit CaseBuilder(SweepCase& c) : case_(c) {}
  void set(const std::string& key, std::string value, io::SourceLocation source = {}, bool flow = false) {
    case_.overrides.push_back({key, std::move(value), std::move(source), flow});
  }
  void set(const PresetKey& key, const io::SourceLocation& source) { set(key.key_path, key.yaml_value, source, key.flow); }
  // The value the case deck will hold for `key` if the sweep sets it.
  std::optional<std::string> value_of(const std::string& key) const {
    for (auto it = case_.overrides.rbegin(); it != case_.overrides.rend(); ++it)
      if (it->key_path == key) return it->yaml_value;
    return std::nullopt;
  }

 private:
  SweepCase& case_;
};

}  // namespace

BaseDeckFacts read_base_deck_facts(const std::filesystem::path& base_deck) {
  const io::LoadedDeck loaded = io::load_deck(base_deck);
  BaseDeckFacts facts;
  if (const io::DeckNode* wind = loaded.root.find("wind")) {
    const io::DeckNode* model = wind->find("model");
    facts.wind_model = model ? model->scalar : "steady";  // the wind schema's default
    if (const io::DeckNode* speed = find_path(loaded.root, {"wind", "speed_m_s"})) facts.wind_speed_m_s = parse_number(speed->scalar);
    if (const io::DeckNode* width = find_path(loaded.root, {"wind", "turbulence", "width_m"}))
      facts.turbulence_width_m = parse_number(width->scalar).value_or(0.0);
  }
  if (const io::DeckNode* waves = loaded.root.find("waves")) {
    const io::DeckNode* model = waves->find("model");
    facts.wave_model = model ? model->scalar : "still";  // the waves schema's default
  }
  facts.rayleigh_ritz_blades = find_path(loaded.root, {"structure", "rotor", "rayleigh_ritz_blade_file"}) != nullptr;
  if (const io::DeckNode* controller = loaded.root.find("controller")) {
    const io::DeckNode* type = controller->find("type");
    facts.controller.type = type ? type->scalar : "baseline";  // the controller schema's default
    if (const io::DeckNode* max = controller->find("max_pitch_rad"))
      facts.controller.max_pitch_rad = parse_number(max->scalar).value_or(facts.controller.max_pitch_rad);
  }
  return facts;
}

std::vector<SweepCase> expand_cases(const SweepSpec& spec, const BaseDeckFacts& base) {
  std::vector<SweepCase> cases;
  std::vector<io::DeckIssue> issues;
  std::set<std::string> seen;  // case names so far
  const double total_s = spec.transient_s + spec.analysis_s;

  for (std::size_t gi = 0; gi < spec.groups.size(); ++gi) {
    const LoadCaseGroup& g = spec.groups[gi];
    const PresetPlan plan = preset_plan(g.preset, spec.turbine, base.controller, spec.transient_s, !g.wind_speeds_m_s.empty());
    const std::vector<Axis> axes = group_axes(g, plan);
    for (const std::vector<std::size_t>& index : combinations(axes, g.combine)) {
      for (int r = 1; r <= g.seeds; ++r) {
        SweepCase c;
        c.group = gi;
        c.realisation = r;
        c.fatigue = g.fatigue;
        CaseBuilder deck(c);
        deck.set("simulation.t_max_s", number_text(total_s));
        for (const PresetKey& key : plan.keys) deck.set(key, g.location);

        std::string name = g.name;
        std::string canonical = spec.name + "|" + g.name;
        std::string wind_canonical = canonical;  // the factors that shape the turbulent field
        for (std::size_t a = 0; a < axes.size(); ++a) {
          for (const PresetKey& key : axes[a].keys[index[a]]) {
            deck.set(key, axes[a].source);
            canonical += "|" + key.key_path + "=" + key.yaml_value;
            if (shapes_turbulence(key.key_path)) wind_canonical += "|" + key.key_path + "=" + key.yaml_value;
          }
          // Wind speeds always name the case; other factors only when they vary in the group.
          const std::string& piece = axes[a].names[index[a]];
          if (axes[a].label == "ws" || axes[a].size() > 1) {
            name += "_" + axes[a].label + name_piece(piece);
            c.factors.emplace_back(axes[a].label, piece);
          }
        }
        canonical += fmt::format("|realisation={}", r);
        wind_canonical += fmt::format("|realisation={}", r);
        if (g.seeds > 1) name += fmt::format("_s{}", r);

        const std::optional<std::string> speed_text = deck.value_of("wind.speed_m_s");
        c.wind_speed_m_s = speed_text ? parse_number(*speed_text) : base.wind_speed_m_s;

        const std::string wind_model = deck.value_of("wind.model").value_or(base.wind_model);
        if (wind_model == "turbulent") {
          // One realisation of the wind for all the variants that do not change it (yaw, fault
          // time, sea): they share a field, as a basis built on TurbSim files shares its files.
          c.wind_seed = case_seed(wind_canonical, "wind");
          deck.set("wind.turbulence.seed", std::to_string(*c.wind_seed));
          // No periodic repeat inside the run: the box must also pass the rotor first, (X0 + reach)/U
          // with X0 half the grid's width (wind/record_length.hpp); the whole width bounds it, since
          // the rotor fits in the grid.
          const std::optional<std::string> width_text = deck.value_of("wind.turbulence.width_m");
          const double width_m = width_text ? parse_number(*width_text).value_or(0.0) : base.turbulence_width_m;
          const double speed = c.wind_speed_m_s.value_or(0.0);
          const double lead_s = speed > 0.0 ? std::ceil(width_m / speed) : 0.0;
          deck.set("wind.turbulence.duration_s", number_text(total_s + lead_s));
        }
        if (g.sea_state.kind != SeaStateSpec::Kind::from_base_deck) {
          if (g.sea_state.kind != SeaStateSpec::Kind::fixed && !c.wind_speed_m_s) {
            issues.push_back({io::DeckIssueKind::missing_key, g.sea_state.location, "sea_state", "",
                              "a wind speed to look the sea state up at (wind_speeds_m_s, or wind.speed_m_s in the base deck)", ""});
            break;
          }
          const SeaState sea = sea_state_at(g.sea_state, c.wind_speed_m_s.value_or(0.0));
          c.hs_m = sea.hs_m;
          c.tp_s = sea.tp_s;
          if (base.wave_model != "jonswap" && base.wave_model != "pm") deck.set("waves.model", "jonswap", g.sea_state.location);
          deck.set("waves.hs_m", number_text(sea.hs_m), g.sea_state.location);
          deck.set("waves.tp_s", number_text(sea.tp_s), g.sea_state.location);
        }
        const std::string wave_model = deck.value_of("waves.model").value_or(base.wave_model);
        if (wave_model == "jonswap" || wave_model == "pm") {
          c.wave_seed = case_seed(canonical, "waves");
          deck.set("waves.seed", std::to_string(*c.wave_seed));
          deck.set("waves.duration_s", number_text(total_s));
        }
        // `set` keys again last, so that they override anything the sweep derived above.
        for (std::size_t a = 0; a < axes.size(); ++a)
          if (axes[a].from_set)
            for (const PresetKey& key : axes[a].keys[index[a]]) deck.set(key, axes[a].source);
        // A seed the spec sets itself is the one the case runs with, and the one the table shows.
        if (c.wind_seed) c.wind_seed = parse_seed(*deck.value_of("wind.turbulence.seed")).value_or(*c.wind_seed);
        if (c.wave_seed) c.wave_seed = parse_seed(*deck.value_of("waves.seed")).value_or(*c.wave_seed);

        c.name = name;
        if (!seen.insert(name).second) {
          issues.push_back({io::DeckIssueKind::out_of_range, g.location, fmt::format("load_cases[{}]", gi), "case name " + name + " twice",
                            "distinct case names", "two values of a factor give the same name piece: make them differ"});
          break;
        }
        cases.push_back(std::move(c));
      }
    }
  }
  if (!issues.empty()) throw io::DeckError(std::move(issues));
  return cases;
}

}  // namespace fowtsim::driver::sweep
