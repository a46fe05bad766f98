// The command line's `--set key.path=value` over a loaded deck (deck.hpp, apply_settings).
#include <algorithm>
#include <cctype>
#include <string>

#include <fmt/format.h>

#include "deck_merge.hpp"
#include "fowtsim/io/deck.hpp"

namespace fowtsim::io {
namespace {

[[noreturn]] void refuse(const std::string& setting, const std::string& why, const std::string& hint) {
  throw InputError({"io.deck", std::nullopt, "--set " + setting, hint}, fmt::format("--set {}: {}", setting, why));
}

bool plain_key(const std::string& key) {
  return !key.empty() && std::all_of(key.begin(), key.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

// Nodes carry no line: the setting is the whole location ("--set a.b: a.b: expected …").
void locate(DeckNode& node, const SourceLocation& at) {
  node.location = at;
  for (DeckEntry& e : node.entries) {
    e.key_location = at;
    locate(e.value, at);
  }
  for (DeckNode& item : node.items) locate(item, at);
}

}  // namespace

void apply_settings(LoadedDeck& deck, const std::vector<std::string>& settings) {
  if (settings.empty()) return;
  std::uint64_t hash = std::stoull(deck.hash, nullptr, 16);
  for (const std::string& setting : settings) {
    const std::size_t equals = setting.find('=');
    if (equals == std::string::npos)
      refuse(setting, "expected key.path=value", "e.g. --set simulation.t_max_s=60 or --set wind.speed_m_s=14");
    const std::string path = setting.substr(0, equals);
    std::vector<std::string> keys;
    for (std::size_t start = 0;;) {
      const std::size_t dot = path.find('.', start);
      keys.push_back(path.substr(start, dot - start));
      if (dot == std::string::npos) break;
      start = dot + 1;
    }
    for (const std::string& key : keys) {
      if (key == "include")
        refuse(setting, "`include` cannot be set from the command line", "include the file from a deck");
      if (!plain_key(key))
        refuse(setting, fmt::format("`{}` is not a key path of plain keys joined by dots", path),
               path.find('[') != std::string::npos ? "a sequence is set whole, e.g. --set output.channels=[RotSpeed, GenPwr]"
                                                   : "e.g. wind.turbulence.seed");
    }
    // Relative paths in the value are taken from the current folder (deck paths are relative to
    // the folder of the file that names them; this "file" has none).
    const SourceLocation origin{"--set " + path, 0, 0};
    DeckNode value = detail::parse_yaml_value(setting.substr(equals + 1), origin.file, path);
    locate(value, origin);
    // Down the key path, making mappings where there are none (as a sweep's case deck does); the
    // last key's value is replaced, or merged key by key when both are mappings (as an including
    // mapping's own keys are). Mappings on the way keep their location: their other keys are
    // written there.
    DeckNode* node = &deck.root;
    std::string node_path;
    for (std::size_t k = 0; k < keys.size(); ++k) {
      node_path += (k ? "." : "") + keys[k];
      auto entry = std::find_if(node->entries.begin(), node->entries.end(), [&](const DeckEntry& e) { return e.key == keys[k]; });
      const bool last = k + 1 == keys.size();
      if (entry == node->entries.end()) {
        node->entries.push_back({keys[k], origin, {}});
        entry = std::prev(node->entries.end());
        entry->value = {DeckNodeKind::map, node_path, origin, {}, {}, {}};
      } else if (!last && entry->value.kind != DeckNodeKind::map) {
        *entry = {keys[k], origin, {DeckNodeKind::map, node_path, origin, {}, {}, {}}};
      }
      if (last) {
        if (entry->value.kind == DeckNodeKind::map && value.kind == DeckNodeKind::map) {
          detail::merge_into(entry->value, std::move(value));
        } else {
          *entry = {keys[k], origin, std::move(value)};
        }
      }
      node = &entry->value;
    }
    hash = fnv1a_64("\n--set ", hash);
    hash = fnv1a_64(setting, hash);
  }
  deck.hash = fmt::format("{:016x}", hash);
}

}  // namespace fowtsim::io
