#include "sweep/case_files.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <optional>

#include <unistd.h>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "run/validate_deck.hpp"

namespace fowtsim::driver::sweep {

namespace fs = std::filesystem;

void SweepLayout::create_directories() const {
  for (const char* sub : {"decks", "cases", "logs", "slurm"}) fs::create_directories(root / sub);
}

void claim_base_deck(const SweepLayout& layout, const fs::path& base_deck) {
  const std::string current = fs::absolute(base_deck).lexically_normal().string();
  const fs::path record = layout.base_deck_record();
  if (std::ifstream in(record); in) {
    std::string recorded;
    std::getline(in, recorded);
    if (!recorded.empty() && recorded != current)
      throw InputError({"sweep", std::nullopt, "--base-deck", fmt::format("--base-deck {}, or another --output-dir", recorded)},
                       fmt::format("{} holds the cases of the base deck {}; this sweep's base deck is {} (it would rewrite "
                                   "every case deck and rerun every case on another model)",
                                   layout.root.string(), recorded, current));
    if (recorded == current) return;
  }
  std::ofstream out(record, std::ios::trunc);
  out << current << '\n';
  if (!out) throw InputError({"sweep", std::nullopt, "output_dir", "a writable folder"}, "cannot write " + record.string());
}

namespace {

// Overrides as nested mappings, keys in first-set order; a later value of a key replaces it.
struct KeyTree {
  std::string key;
  std::optional<std::string> value;
  std::vector<KeyTree> children;
  bool flow = false;  // value is flow-style YAML, written as is

  KeyTree& child(const std::string& name) {
    for (KeyTree& c : children)
      if (c.key == name) return c;
    children.push_back({name, std::nullopt, {}});
    return children.back();
  }
};

// Plain YAML scalars stay plain (numbers, words, paths); anything else is double-quoted.
std::string yaml_scalar(const std::string& text) {
  const bool plain = !text.empty() && std::all_of(text.begin(), text.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '.' || c == '+' || c == '-' || c == '/';
  });
  if (plain) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

void emit(const KeyTree& node, int depth, std::string& out) {
  for (const KeyTree& c : node.children) {
    out.append(static_cast<std::size_t>(2 * depth), ' ');
    out += c.key;
    out += ':';
    if (c.value) {
      out += ' ';
      out += c.flow ? *c.value : yaml_scalar(*c.value);
      out += '\n';
    } else {
      out += "\n";
      emit(c, depth + 1, out);
    }
  }
}

// A problem in a key the case deck sets is reported where the spec sets it (if it does), naming the case.
io::DeckIssue relocate(io::DeckIssue issue, const SweepCase& c) {
  for (auto it = c.overrides.rbegin(); it != c.overrides.rend(); ++it) {
    if (it->key_path != issue.path) continue;
    if (it->source.line > 0) issue.location = it->source;
    break;
  }
  issue.hint = issue.hint.empty() ? "in case " + c.name : issue.hint + " (case " + c.name + ")";
  return issue;
}

}  // namespace

std::string case_deck_text(const SweepSpec& spec, const SweepCase& c, const fs::path& deck_dir) {
  KeyTree tree;
  for (const DeckOverride& o : c.overrides) {
    KeyTree* node = &tree;
    std::size_t start = 0;
    while (true) {
      const std::size_t dot = o.key_path.find('.', start);
      node = &node->child(o.key_path.substr(start, dot - start));
      if (dot == std::string::npos) break;
      node->value.reset();  // a mapping now, whatever was set there before
      start = dot + 1;
    }
    node->children.clear();
    node->value = o.yaml_value;
    node->flow = o.flow;
  }
  // Relative when the decks and the base deck share a top folder (the sweep folder can move with
  // the project), absolute otherwise (no climb to the file-system root and down again).
  const fs::path base = fs::absolute(spec.base_deck).lexically_normal(), decks = fs::absolute(deck_dir).lexically_normal();
  const bool shared_top = std::next(base.begin()) != base.end() && std::next(decks.begin()) != decks.end() &&
                          *std::next(base.begin()) == *std::next(decks.begin());
  const fs::path include = shared_top ? base.lexically_relative(decks) : base;
  std::string text = fmt::format(
      "# Case {} of the sweep {} ({}), written by `fowtsim sweep`: the base deck with the keys below\n"
      "# set over it. Rerun it alone with `fowtsim run THIS_FILE -o OUT.h5`.\n"
      "include: {}\n",
      c.name, spec.name, spec.spec_path.string(), yaml_scalar(include.generic_string()));
  emit(tree, 0, text);
  return text;
}

namespace {

// Writes each case deck into `deck_dir` (an unchanged one is left alone: a Slurm task may be reading
// it while --collect runs) and checks it as `fowtsim run` would (validate_scene_deck). Problems are
// reported at `shown_dir`, where the sweep keeps the decks (the same text line for line), each
// naming its case; a key the spec sets is reported at its spec line. Every case's problems together.
std::vector<std::string> write_and_check(const SweepSpec& spec, const std::vector<SweepCase>& cases, const fs::path& deck_dir,
                                         const fs::path& shown_dir) {
  fs::create_directories(deck_dir);
  std::vector<std::string> hashes;
  std::vector<io::DeckIssue> issues;
  std::vector<std::pair<std::string, std::vector<std::string>>> rule_errors;  // message, its cases
  for (const SweepCase& c : cases) {
    const fs::path path = deck_dir / (c.name + ".yaml"), shown = shown_dir / (c.name + ".yaml");
    const std::string text = case_deck_text(spec, c, path.parent_path());
    if (std::ifstream in(path, std::ios::binary); !in || std::string(std::istreambuf_iterator<char>(in), {}) != text) {
      std::ofstream out(path, std::ios::binary | std::ios::trunc);
      out << text;
      if (!out) throw InputError({"sweep", std::nullopt, "output_dir", "a writable folder"}, "cannot write " + path.string());
    }
    try {
      hashes.push_back(validate_scene_deck(path));
    } catch (const io::DeckError& e) {
      // A problem of the base deck itself is the same in every case: reported once.
      for (const io::DeckIssue& issue : e.issues()) {
        io::DeckIssue located = issue;
        if (issue.location.file == path.string()) {
          located.location.file = shown.string();
          located = relocate(located, c);
        }
        if (std::none_of(issues.begin(), issues.end(), [&](const io::DeckIssue& i) { return i.to_string() == located.to_string(); }))
          issues.push_back(std::move(located));
      }
    } catch (const InputError& e) {
      // A rule across keys the scene applies (e.g. pitch limits): its message names the deck by
      // file:line and the keys concerned.
      std::string message = e.what();
      for (std::size_t at = message.find(path.string()); at != std::string::npos;
           at = message.find(path.string(), at + shown.string().size()))
        message.replace(at, path.string().size(), shown.string());
      for (std::size_t at = message.find('\n'); at != std::string::npos; at = message.find('\n', at + 1)) message.insert(at + 1, "    ");
      const auto same = std::find_if(rule_errors.begin(), rule_errors.end(), [&](const auto& r) { return r.first == message; });
      if (same == rule_errors.end()) rule_errors.push_back({message, {c.name}});
      else same->second.push_back(c.name);
    }
  }
  if (rule_errors.empty() && !issues.empty()) throw io::DeckError(std::move(issues));
  if (rule_errors.empty()) return hashes;
  std::string lines = "case decks that `fowtsim run` would reject:";
  for (const io::DeckIssue& issue : issues) lines += "\n  " + issue.to_string();
  for (const auto& [message, names] : rule_errors) {
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    lines += fmt::format("\n  case{} {}: {}", names.size() > 1 ? "s" : "", list, message);
  }
  throw InputError({"sweep", std::nullopt, "case decks", "fix the keys named, in the spec or its base deck"}, lines);
}

}  // namespace

std::vector<std::string> write_case_decks(const SweepSpec& spec, const std::vector<SweepCase>& cases, const SweepLayout& layout) {
  return write_and_check(spec, cases, layout.root / "decks", layout.root / "decks");
}

void check_case_decks(const SweepSpec& spec, const std::vector<SweepCase>& cases, const SweepLayout& layout) {
  const fs::path scratch = fs::temp_directory_path() / fmt::format("fowtsim-sweep-check-{}", ::getpid());
  struct Removed {
    fs::path dir;
    ~Removed() {
      std::error_code ignored;
      fs::remove_all(dir, ignored);
    }
  } removed{scratch};
  write_and_check(spec, cases, scratch, layout.root / "decks");
}

void write_exit_code(const SweepLayout& layout, const std::string& case_name, int exit_code) {
  std::ofstream(layout.exit_code(case_name), std::ios::trunc) << exit_code << "\n";
}

}  // namespace fowtsim::driver::sweep
