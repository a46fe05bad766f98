#include "fowtsim/io/deck.hpp"

#include "deck_merge.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>

namespace fowtsim::io {
namespace fs = std::filesystem;

std::string SourceLocation::to_string() const {
  if (line == 0) return file;
  return fmt::format("{}:{}:{}", file, line, column);
}

const DeckNode* DeckNode::find(std::string_view key) const {
  for (const DeckEntry& entry : entries) {
    if (entry.key == key) return &entry.value;
  }
  return nullptr;
}

std::string DeckIssue::to_string() const {
  std::string line = location.to_string() + ": ";
  if (!path.empty()) line += path + ": ";
  switch (kind) {
    case DeckIssueKind::yaml_syntax:
      line += "invalid YAML: " + found;
      break;
    case DeckIssueKind::file_unreadable:
      line += "cannot open " + found;
      break;
    case DeckIssueKind::include_cycle:
      line += "include cycle " + found;
      break;
    case DeckIssueKind::duplicate_key:
      line += "duplicate key, first written at " + found;
      break;
    case DeckIssueKind::unknown_key:
      line += "unknown key; expected one of the keys " + expected;
      break;
    case DeckIssueKind::missing_key:
      line += "missing required key; expected " + expected;
      break;
    default:
      line += "expected " + expected + ", found " + found;
      break;
  }
  if (!hint.empty()) line += "; " + hint;
  return line;
}

namespace {

std::string error_message(const std::vector<DeckIssue>& issues) {
  std::string text =
      fmt::format("{} problem{} in the input deck:", issues.size(), issues.size() == 1 ? "" : "s");
  for (const DeckIssue& issue : issues) {
    text += '\n';
    text += issue.to_string();
  }
  return text;
}

}  // namespace

DeckError::DeckError(std::vector<DeckIssue> issues)
    : InputError({"io.deck", {}, {}, {}}, error_message(issues)), issues_(std::move(issues)) {}

std::uint64_t fnv1a_64(std::string_view bytes, std::uint64_t hash) {
  for (const char byte : bytes) {
    hash ^= static_cast<unsigned char>(byte);
    hash *= 0x100000001b3ULL;  // FNV 64-bit prime
  }
  return hash;
}

namespace {

std::optional<std::string> read_bytes(const fs::path& file) {
  if (!fs::is_regular_file(file)) return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string child_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

}  // namespace

void detail::merge_into(DeckNode& base, DeckNode over) {
  for (DeckEntry& entry : over.entries) {
    auto same_key = std::find_if(base.entries.begin(), base.entries.end(),
                                 [&](const DeckEntry& e) { return e.key == entry.key; });
    if (same_key == base.entries.end()) {
      base.entries.push_back(std::move(entry));
    } else if (same_key->value.kind == DeckNodeKind::map && entry.value.kind == DeckNodeKind::map) {
      same_key->key_location = entry.key_location;
      merge_into(same_key->value, std::move(entry.value));
    } else {
      *same_key = std::move(entry);
    }
  }
  base.location = over.location;  // the mapping is where its overriding keys are written
}

namespace {

using detail::merge_into;

// Converts yaml-cpp nodes into DeckNodes, following includes. Problems are collected in
// `issues` so that one run reports them all; a file that fails is left out of the tree.
class Loader {
 public:
  // One YAML value given as text (not a file), located at `origin`.
  DeckNode load_text(const std::string& text, const std::string& origin, const std::string& path) {
    DeckNode node;
    try {
      node = convert(YAML::Load(text), origin, path, {origin, 0, 0});
    } catch (const YAML::Exception& error) {
      DeckIssue issue;  // built field by field: GCC 12 warns of an aggregate here (maybe-uninitialized)
      issue.kind = DeckIssueKind::yaml_syntax;
      issue.location = SourceLocation{origin, 0, 0};
      issue.path = path;
      issue.found = error.msg;
      issue.expected = "a YAML value";
      add(std::move(issue));
    }
    if (!issues_.empty()) throw DeckError(std::move(issues_));
    return node;
  }

  LoadedDeck load(const fs::path& top) {
    LoadedDeck deck;
    if (std::optional<DeckNode> root = load_file(top, {top.string(), 0, 0}, "", "")) {
      deck.root = std::move(*root);
    }
    if (deck.root.kind == DeckNodeKind::null) {  // an empty deck is an empty mapping
      deck.root.kind = DeckNodeKind::map;
      deck.root.location = {top.string(), 1, 1};
    }
    if (!issues_.empty()) throw DeckError(std::move(issues_));
    deck.files = std::move(files_);
    deck.hash = fmt::format("{:016x}", hash_);
    return deck;
  }

 private:
  // Parses `file` into a node placed at key path `path`. `included_at` is the location of the
  // include that names it (the file itself for the top deck), `include_path` the key path there.
  std::optional<DeckNode> load_file(const fs::path& file, const SourceLocation& included_at,
                                    const std::string& path, const std::string& include_path) {
    std::error_code error;
    fs::path identity = fs::weakly_canonical(file, error);
    if (error) identity = fs::absolute(file);
    const auto open = std::find(stack_.begin(), stack_.end(), identity);
    if (open != stack_.end()) {
      std::string chain;
      for (auto it = open; it != stack_.end(); ++it) {
        chain += display_[static_cast<std::size_t>(it - stack_.begin())] + " -> ";
      }
      add({DeckIssueKind::include_cycle, included_at, include_path, chain + file.string(),
           "an include graph without cycles", "remove one of these includes"});
      return std::nullopt;
    }
    const std::string* bytes = bytes_of(file, identity);
    if (bytes == nullptr) {
      std::error_code error;
      const bool directory = fs::is_directory(file, error);
      add({DeckIssueKind::file_unreadable, included_at, include_path,
           file.string() + (directory ? " (it is a directory, not a file)" : " (no such file, or not readable)"), "a readable file",
           include_path.empty() ? "" : "include paths are relative to the including file"});
      return std::nullopt;
    }
    YAML::Node yaml;
    try {
      // A deck is one YAML document: a second one (after "---") would be silently ignored by
      // YAML::Load, valid or not, so it is refused where it starts.
      const std::vector<YAML::Node> documents = YAML::LoadAll(*bytes);
      if (documents.size() > 1) {
        add({DeckIssueKind::yaml_syntax, second_document_start(*bytes, file), "",
             fmt::format("{} YAML documents (separated by ---) in one deck file", documents.size()), "one document",
             "put the keys of every document into one, or into files joined by include"});
        return std::nullopt;
      }
      if (!documents.empty()) yaml = documents.front();
    } catch (const YAML::Exception& error) {
      add({DeckIssueKind::yaml_syntax,
           {file.string(), error.mark.line + 1, error.mark.column + 1},
           "",
           error.msg,
           "valid YAML",
           ""});
      return std::nullopt;
    }
    stack_.push_back(identity);
    display_.push_back(file.string());
    DeckNode node = convert(yaml, file, path, {file.string(), 1, 1});
    stack_.pop_back();
    display_.pop_back();
    return node;
  }

  // The bytes of `file`, read once per run however often it is included; records the file and
  // advances the deck hash in load order. nullptr if it cannot be read.
  const std::string* bytes_of(const fs::path& file, const fs::path& identity) {
    if (auto cached = bytes_.find(identity); cached != bytes_.end()) return &cached->second;
    std::optional<std::string> bytes = read_bytes(file);
    if (!bytes) return nullptr;
    files_.push_back(file);
    hash_ = fnv1a_64(*bytes, hash_);
    return &bytes_.emplace(identity, std::move(*bytes)).first->second;
  }

  // `fallback` locates nodes yaml-cpp gives no useful mark: empty values (whose mark points past
  // the key, often to the next line) and an empty document.
  DeckNode convert(const YAML::Node& yaml, const fs::path& file, const std::string& path,
                   const SourceLocation& fallback) {
    DeckNode node;
    node.path = path;
    node.location = fallback;
    // YAML aliases can expand a small file without bound (a "billion laughs" deck grew to 24 GB):
    // stop at a node count no real deck comes near.
    if (++nodes_ > kMaxNodes) {
      if (!too_large_)
        add({DeckIssueKind::yaml_syntax, location_of(yaml, file, fallback), path,
             fmt::format("the deck expands to more than {} values (nested YAML aliases?)", kMaxNodes),
             "a deck of ordinary size", "write the values out instead of aliasing aliases"});
      too_large_ = true;
      return node;
    }
    if (yaml.IsNull()) return node;
    node.location = location_of(yaml, file, fallback);
    if (yaml.IsScalar()) {
      node.kind = DeckNodeKind::scalar;
      node.scalar = yaml.Scalar();
    } else if (yaml.IsSequence()) {
      node.kind = DeckNodeKind::sequence;
      for (std::size_t i = 0; i < yaml.size(); ++i) {
        node.items.push_back(convert(yaml[i], file, fmt::format("{}[{}]", path, i), node.location));
      }
    } else if (yaml.IsMap()) {
      convert_map(yaml, file, node);
    }
    return node;
  }

  void convert_map(const YAML::Node& yaml, const fs::path& file, DeckNode& node) {
    node.kind = DeckNodeKind::map;
    DeckNode own = node;       // keys written in this mapping
    DeckNode included = node;  // keys from its includes, overridden by `own` at the end
    std::map<std::string, SourceLocation> seen;  // key -> where first written
    for (auto it = yaml.begin(); it != yaml.end(); ++it) {
      const SourceLocation key_location = location_of(it->first, file, node.location);
      if (!it->first.IsScalar()) {
        add({DeckIssueKind::wrong_type, key_location, node.path, "a complex key",
             "a plain key name", ""});
        continue;
      }
      const std::string key = it->first.Scalar();
      const std::string path = child_path(node.path, key);
      if (const auto [first, inserted] = seen.emplace(key, key_location); !inserted) {
        add({DeckIssueKind::duplicate_key, key_location, path, first->second.to_string(), "", ""});
        continue;
      }
      DeckEntry entry{key, key_location, convert(it->second, file, path, key_location)};
      if (key == "include") {
        include(entry, file, node.path, included);
      } else {
        own.entries.push_back(std::move(entry));
      }
    }
    merge_into(included, std::move(own));
    node = std::move(included);
  }

  // Merges each file named by an `include` entry into `target`, in order.
  void include(const DeckEntry& entry, const fs::path& file, const std::string& path,
               DeckNode& target) {
    std::vector<const DeckNode*> names;
    if (entry.value.kind == DeckNodeKind::scalar) names.push_back(&entry.value);
    for (const DeckNode& item : entry.value.items) names.push_back(&item);
    const bool valid = !names.empty() && std::all_of(names.begin(), names.end(), [](auto* n) {
      return n->kind == DeckNodeKind::scalar;
    });
    if (!valid) {
      add({DeckIssueKind::wrong_type, entry.value.location, entry.value.path,
           "a value that is not a file name", "a file path or a sequence of file paths", ""});
      return;
    }
    for (const DeckNode* name : names) {
      const fs::path included = (file.parent_path() / name->scalar).lexically_normal();
      std::optional<DeckNode> root = load_file(included, name->location, path, name->path);
      if (!root || root->kind == DeckNodeKind::null) continue;
      if (root->kind != DeckNodeKind::map) {
        add({DeckIssueKind::wrong_type, root->location, name->path,
             root->kind == DeckNodeKind::scalar ? "a scalar" : "a sequence",
             "an included file holding a mapping", ""});
        continue;
      }
      merge_into(target, std::move(*root));
    }
  }

  // Where the second document of a multi-document file starts: the line of its "---" marker (a
  // document may also open with one), else the file's first line.
  static SourceLocation second_document_start(const std::string& bytes, const fs::path& file) {
    int markers = 0, line = 1;
    bool content_before = false;  // a first document without a leading "---"
    for (std::size_t pos = 0; pos < bytes.size(); ++line) {
      const std::size_t end = std::min(bytes.find('\n', pos), bytes.size());
      const std::string_view text(bytes.data() + pos, end - pos);
      pos = end + 1;
      if (text.starts_with("---") && (text.size() == 3 || text[3] == ' ' || text[3] == '\t' || text[3] == '\r')) {
        if (++markers == (content_before ? 1 : 2)) return {file.string(), line, 1};
      } else if (markers == 0 && !text.empty() && text.front() != '#' && text.find_first_not_of(" \t\r") != std::string_view::npos &&
                 text.front() != '%') {
        content_before = true;
      }
    }
    return {file.string(), 1, 1};
  }

  // yaml-cpp marks are 0-based; ours are 1-based.
  static SourceLocation location_of(const YAML::Node& yaml, const fs::path& file,
                                    const SourceLocation& fallback) {
    const YAML::Mark mark = yaml.Mark();
    if (mark.line < 0) return fallback;
    return {file.string(), mark.line + 1, mark.column + 1};
  }

  void add(DeckIssue issue) { issues_.push_back(std::move(issue)); }

  std::vector<DeckIssue> issues_;
  std::vector<fs::path> stack_;            // canonical paths of the files being converted
  std::vector<std::string> display_;       // the same files as named in messages
  std::map<fs::path, std::string> bytes_;  // canonical path -> file bytes
  std::vector<fs::path> files_;            // files read, in load order
  std::uint64_t hash_ = fnv1a_64_offset;   // FNV-1a over files_ so far
  static constexpr std::size_t kMaxNodes = 2'000'000;  // values in the whole deck, aliases expanded
  std::size_t nodes_ = 0;
  bool too_large_ = false;
};

}  // namespace

LoadedDeck load_deck(const fs::path& file) { return Loader().load(file); }

DeckNode detail::parse_yaml_value(const std::string& text, const std::string& origin, const std::string& path) {
  return Loader().load_text(text, origin, path);
}

std::string deck_hash(const std::vector<fs::path>& files) {
  std::uint64_t hash = fnv1a_64_offset;
  for (const fs::path& file : files) {
    const std::optional<std::string> bytes = read_bytes(file);
    if (!bytes) {
      throw InputError({"io.deck", {}, file.string(), "check the file exists and is readable"},
                       "cannot read " + file.string() + " to hash it");
    }
    hash = fnv1a_64(*bytes, hash);
  }
  return fmt::format("{:016x}", hash);
}

}  // namespace fowtsim::io
