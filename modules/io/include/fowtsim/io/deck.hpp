#pragma once
// Input decks as a tree that remembers where every value came from (DESIGN.md §5). YAML files
// are loaded with their `include:`s merged, so validation (schema.hpp) and any later check by a
// module can name the file:line:col and key path of whatever it rejects.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "fowtsim/core/error.hpp"

namespace fowtsim::io {

struct SourceLocation {
  std::string file;  // deck file as opened: the path given to load_deck, or an include path
                     // resolved against the directory of the file that includes it
  int line = 0;      // 1-based line; 0 when the whole file is concerned (e.g. it cannot be opened)
  int column = 0;    // 1-based column; 0 when line is 0

  // "file:line:col", or just "file" when line is 0.
  std::string to_string() const;
};

enum class DeckNodeKind { null, scalar, map, sequence };

struct DeckEntry;

struct DeckNode {
  DeckNodeKind kind = DeckNodeKind::null;  // an empty value (`key:` or `~`) is null
  std::string path;                // key path from the deck root, e.g. "simulation.dt_coupling_s",
                                   // "channels[2]"; "" for the root
  SourceLocation location;         // where the value starts; for an empty value, where its key is
  std::string scalar;              // scalar text as written, quotes removed; "" unless scalar
  std::vector<DeckEntry> entries;  // mapping entries in file order, keys unique; empty unless map
  std::vector<DeckNode> items;     // sequence items in order; empty unless sequence

  // The value stored under `key` in a mapping; nullptr when absent or when this is no mapping.
  const DeckNode* find(std::string_view key) const;
};

struct DeckEntry {
  std::string key;  // key as written
  SourceLocation
      key_location;  // where the key is written (in an included file if it came from one)
  DeckNode value;    // the value; value.path is the mapping's path + "." + key
};

enum class DeckIssueKind {
  yaml_syntax,      // the YAML parser rejected a file
  file_unreadable,  // the deck file or an included file cannot be opened
  include_cycle,    // a file includes itself, directly or through other files
  duplicate_key,    // the same key twice in one mapping
  unknown_key,      // a key the schema does not declare
  missing_key,      // a required key is absent
  wrong_type,       // e.g. text where a number is expected, a mapping where a scalar is expected
  out_of_range,     // a number outside its declared range, or a sequence of the wrong length
  not_in_choices,   // a value outside the allowed list of a choice
};

struct DeckIssue {
  DeckIssueKind kind = DeckIssueKind::wrong_type;  // what went wrong
  SourceLocation location;  // the offending value or key; for a missing key, the mapping lacking it
  std::string path;         // key path concerned, e.g. "simulation.t_max_s"; "" for a whole file
  std::string found;        // what the deck holds, e.g. "-0.1", "a mapping", or the parser message
  std::string expected;     // what was wanted: type with range and unit, allowed values or keys
  std::string hint;         // optional remedy, e.g. "did you mean `dt_coupling_s`?"; may be ""

  // One line, e.g. "inputs/x.yaml:12:5: simulation.dt_coupling_s: expected a number > 0 [s],
  // found -0.1".
  std::string to_string() const;
};

// Every problem found in a deck, reported together; what() holds one issue per line.
class DeckError : public InputError {
 public:
  explicit DeckError(std::vector<DeckIssue> issues);

  const std::vector<DeckIssue>& issues() const { return issues_; }

 private:
  std::vector<DeckIssue> issues_;
};

struct LoadedDeck {
  DeckNode root;                             // top-level mapping with all includes merged
  std::vector<std::filesystem::path> files;  // files read: the deck first, then includes in
                                             // load order, each once
  std::string hash;                          // deck_hash of `files`, from the bytes as loaded
};

// Loads a YAML deck and merges its includes: a mapping's `include: path` or `include: [paths]`
// (relative to the including file) merges the included files' top-level mappings in order, then
// the mapping's own keys override them (nested mappings merge key by key; sequences and scalars
// are replaced). Throws DeckError listing every syntax error, unreadable file, include cycle and
// duplicate key.
LoadedDeck load_deck(const std::filesystem::path& file);

// Sets `key.path=value` settings (the command line's `--set`, in order) over a loaded deck, as a
// sweep case deck sets its keys over its base deck: the value is YAML (a scalar, or a flow sequence
// `[1, 2]` or mapping `{a: 1}`), mappings on the way are created or merged key by key, anything
// else under the key is replaced. Every node a setting brings is located at "--set key.path", so a
// later schema check names the setting and the key (an unknown key with its "did you mean"). A
// relative file path in a value is taken from the current folder. The deck's hash continues over
// the settings: a run with settings is traced (and restarted) as a deck of its own. Throws
// InputError naming the setting if it is not `key.path=value` with dotted plain keys, DeckError if
// its value is not YAML.
void apply_settings(LoadedDeck& deck, const std::vector<std::string>& settings);

// FNV-1a 64-bit of `bytes`, continuing from `hash` so several buffers chain into one digest.
inline constexpr std::uint64_t fnv1a_64_offset = 0xcbf29ce484222325ULL;
std::uint64_t fnv1a_64(std::string_view bytes, std::uint64_t hash = fnv1a_64_offset);

// Content hash of a deck: FNV-1a 64-bit over the bytes of `files` concatenated in order, as 16
// lower-case hex digits. Recorded in run outputs so a result can be traced to its exact inputs.
// Throws InputError if a file cannot be read.
std::string deck_hash(const std::vector<std::filesystem::path>& files);

}  // namespace fowtsim::io
