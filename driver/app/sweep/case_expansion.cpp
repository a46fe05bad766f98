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

// One varied quantity of a group: its values and what it sets.
struct Axis {
  std::string label;                // name piece prefix ("ws", "yaw", "wh", or the key's last part)
  std::string deck_key;             // key it sets (also its name in the canonical case text)
  std::vector<std::string> values;  // YAML scalar text per value
  io::SourceLocation source;        // where the values are written in the spec
};

// Index of each axis per factor combination, the first axis outermost.
std::vector<std::vector<std::size_t>> combinations(const std::vector<Axis>& axes, Combination combine) {
  std::vector<std::vector<std::size_t>> result;
  if (combine == Combination::zip) {
    std::size_t length = 1;
    for (const Axis& a : axes) length = std::max(length, a.values.size());
    for (std::size_t i = 0; i < length; ++i) {
      std::vector<std::size_t> index;
      for (const Axis& a : axes) index.push_back(a.values.size() == 1 ? 0 : i);
      result.push_back(std::move(index));
    }
    return result;
  }
  std::vector<std::size_t> index(axes.size(), 0);
  while (true) {
    result.push_back(index);
    std::size_t k = axes.size();
    while (k > 0 && ++index[k - 1] == axes[k - 1].values.size()) index[--k] = 0;
    if (k == 0) return result;
  }
}

std::vector<Axis> group_axes(const LoadCaseGroup& g) {
  auto numbers = [](const std::vector<double>& v) {
    std::vector<std::string> text;
    for (const double x : v) text.push_back(number_text(x));
    return text;
  };
  std::vector<Axis> axes;
  if (!g.wind_speeds_m_s.empty()) axes.push_back({"ws", "wind.speed_m_s", numbers(g.wind_speeds_m_s), g.location});
  const std::vector<double> yaw =
      !g.yaw_misalignment_deg.empty() ? g.yaw_misalignment_deg
      : g.preset == "dlc6.1"          ? kDlc61YawMisalignmentDeg
                                      : std::vector<double>{};
  if (!yaw.empty()) axes.push_back({"yaw", "wind.direction_deg", numbers(yaw), g.location});
  if (!g.wave_heading_deg.empty()) axes.push_back({"wh", "waves.heading_deg", numbers(g.wave_heading_deg), g.location});
  for (const KeyFactor& f : g.set) {
    const std::size_t dot = f.key_path.rfind('.');
    axes.push_back({dot == std::string::npos ? f.key_path : f.key_path.substr(dot + 1), f.key_path, f.values, f.location});
  }
  return axes;
}

class CaseBuilder {
 public:
  explicit CaseBuilder(SweepCase& c) : case_(c) {}
  void set(const std::string& key, std::string value, io::SourceLocation source = {}) {
    case_.overrides.push_back({key, std::move(value), std::move(source)});
  }
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
    const std::vector<Axis> axes = group_axes(g);
    for (const std::vector<std::size_t>& index : combinations(axes, g.combine)) {
      for (int r = 1; r <= g.seeds; ++r) {
        SweepCase c;
        c.group = gi;
        c.realisation = r;
        c.fatigue = g.fatigue;
        CaseBuilder deck(c);
        deck.set("simulation.t_max_s", number_text(total_s));
        for (const auto& [key, value] : preset_deck_keys(g.preset, spec.turbine, base.controller)) deck.set(key, value, g.location);

        std::string name = g.name;
        std::string canonical = spec.name + "|" + g.name;
        for (std::size_t a = 0; a < axes.size(); ++a) {
          const std::string& value = axes[a].values[index[a]];
          deck.set(axes[a].deck_key, value, axes[a].source);
          canonical += "|" + axes[a].deck_key + "=" + value;
          // Wind speeds always name the case; other factors only when they vary in the group.
          if (axes[a].label == "ws" || axes[a].values.size() > 1) {
            name += "_" + axes[a].label + name_piece(value);
            c.factors.emplace_back(axes[a].label, value);
          }
        }
        canonical += fmt::format("|realisation={}", r);
        if (g.seeds > 1) name += fmt::format("_s{}", r);

        const std::optional<std::string> speed_text = deck.value_of("wind.speed_m_s");
        c.wind_speed_m_s = speed_text ? parse_number(*speed_text) : base.wind_speed_m_s;

        const std::string wind_model = deck.value_of("wind.model").value_or(base.wind_model);
        if (wind_model == "turbulent") {
          c.wind_seed = case_seed(canonical, "wind");
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
        for (std::size_t a = axes.size() - g.set.size(); a < axes.size(); ++a)
          deck.set(axes[a].deck_key, axes[a].values[index[a]], axes[a].source);
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
