#include "fowtsim/io/schema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace fowtsim::io {
namespace {

// ---- Scalar parsing: one definition shared by validation, defaults and typed reads ----------

std::optional<double> parse_number(std::string_view text) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::optional<std::int64_t> parse_integer(std::string_view text) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-') text.remove_prefix(1);
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// YAML 1.2 core booleans only: `yes`/`on` are YAML 1.1 and too easy to write by accident.
std::optional<bool> parse_boolean(std::string_view text) {
  if (text == "true" || text == "True" || text == "TRUE") return true;
  if (text == "false" || text == "False" || text == "FALSE") return false;
  return std::nullopt;
}

// ---- Text for messages and documentation ---------------------------------------------------

std::string join(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& word : words) text += (text.empty() ? "" : ", ") + word;
  return text;
}

std::string range_text(const SchemaSpec& spec) {
  std::string text;
  if (spec.lower)
    text += fmt::format(" {} {}", spec.lower->inclusive ? ">=" : ">", spec.lower->value);
  if (spec.lower && spec.upper) text += " and";
  if (spec.upper)
    text += fmt::format(" {} {}", spec.upper->inclusive ? "<=" : "<", spec.upper->value);
  return text;
}

std::string items_text(const SchemaSpec& spec) {
  if (spec.max_items && *spec.max_items == spec.min_items) {
    return fmt::format(" ({} items)", spec.min_items);
  }
  if (spec.max_items && spec.min_items > 0) {
    return fmt::format(" ({} to {} items)", spec.min_items, *spec.max_items);
  }
  if (spec.max_items) return fmt::format(" (at most {} items)", *spec.max_items);
  if (spec.min_items > 0) return fmt::format(" (at least {} items)", spec.min_items);
  return "";
}

// The type with its constraints, without an article: "number > 0 [s]", "one of a, b".
std::string type_text(const SchemaSpec& spec) {
  const std::string unit = spec.unit.empty() ? "" : " [" + spec.unit + "]";
  switch (spec.type) {
    case SchemaType::number:
      return "number" + range_text(spec) + unit;
    case SchemaType::integer:
      return "integer" + range_text(spec) + unit;
    case SchemaType::boolean:
      return "boolean";
    case SchemaType::string:
      return "string";
    case SchemaType::choice:
      return "one of " + join(spec.choices);
    case SchemaType::map:
      return "mapping";
    case SchemaType::map_of:
      return "mapping of names to " + type_text(spec.element->spec());
    case SchemaType::sequence:
      return "sequence" + items_text(spec) + " of " + type_text(spec.element->spec());
  }
  return "";
}

// What a value must be, as a message says it: "a number > 0 [s]", "an integer >= 1".
std::string expected_text(const SchemaSpec& spec) {
  switch (spec.type) {
    case SchemaType::boolean:
      return "true or false";
    case SchemaType::choice:
      return type_text(spec);
    case SchemaType::integer:
      return "an " + type_text(spec);
    default:
      return "a " + type_text(spec);
  }
}

// What a non-scalar value is, as a message says it.
std::string found_text(const DeckNode& node) {
  switch (node.kind) {
    case DeckNodeKind::null:
      return "an empty value";
    case DeckNodeKind::map:
      return "a mapping";
    case DeckNodeKind::sequence:
      return "a sequence";
    case DeckNodeKind::scalar:
      return node.scalar.empty() ? "\"\"" : node.scalar;
  }
  return "";
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
    }
  }
  return row[b.size()];
}

// "did you mean `x`?" for the closest candidate, if it is close enough to be a typo or is the
// written key with its unit suffix forgotten (`blade_pitch` for `blade_pitch_deg`).
std::string suggestion(std::string_view written, const std::vector<std::string>& candidates) {
  const std::size_t limit = std::max<std::size_t>(2, written.size() / 3);
  const std::string* best = nullptr;
  std::size_t best_distance = limit + 1;
  for (const std::string& candidate : candidates) {
    const bool suffix_forgotten = candidate.starts_with(std::string(written) + "_");
    const std::size_t distance = suffix_forgotten ? 1 : edit_distance(written, candidate);
    if (distance < best_distance) {
      best = &candidate;
      best_distance = distance;
    }
  }
  return best ? fmt::format("did you mean `{}`?", *best) : "";
}

// For "12.1 rpm" where a number is expected: the unit belongs in the key name, not the value.
std::string unit_in_value_hint(const SchemaSpec& spec, const std::string& text) {
  const std::size_t space = text.find_first_of(" \t");
  if (space == std::string::npos || !parse_number(text.substr(0, space))) return "";
  const std::string number = text.substr(0, space);
  if (spec.unit.empty())
    return fmt::format("write the plain number {}; this value has no unit", number);
  return fmt::format("write the plain number {}: the key name says the unit ({})", number,
                     spec.unit);
}

// ---- Validation ----------------------------------------------------------------------------

std::vector<std::string> field_keys(const SchemaSpec& spec) {
  std::vector<std::string> keys;
  for (const SchemaField& field : spec.fields) keys.push_back(field.key);
  return keys;
}

const SchemaField* find_field(const SchemaSpec& spec, std::string_view key) {
  for (const SchemaField& field : spec.fields) {
    if (field.key == key) return &field;
  }
  return nullptr;
}

bool in_range(const SchemaSpec& spec, double value) {
  if (spec.lower &&
      (spec.lower->inclusive ? value < spec.lower->value : value <= spec.lower->value)) {
    return false;
  }
  return !(spec.upper &&
           (spec.upper->inclusive ? value > spec.upper->value : value >= spec.upper->value));
}

// The problem with a scalar value, if any (number, integer, boolean, string, choice).
std::optional<DeckIssue> scalar_problem(const SchemaSpec& spec, const DeckNode& node) {
  auto issue = [&](DeckIssueKind kind, std::string hint = "") {
    return DeckIssue{kind, node.location, node.path, found_text(node), expected_text(spec), hint};
  };
  if (node.kind != DeckNodeKind::scalar) return issue(DeckIssueKind::wrong_type);
  const std::string& text = node.scalar;
  switch (spec.type) {
    case SchemaType::number: {
      const std::optional<double> value = parse_number(text);
      if (!value) return issue(DeckIssueKind::wrong_type, unit_in_value_hint(spec, text));
      if (!in_range(spec, *value)) return issue(DeckIssueKind::out_of_range);
      return std::nullopt;
    }
    case SchemaType::integer: {
      const std::optional<std::int64_t> value = parse_integer(text);
      if (!value) return issue(DeckIssueKind::wrong_type, unit_in_value_hint(spec, text));
      if (!in_range(spec, static_cast<double>(*value))) return issue(DeckIssueKind::out_of_range);
      return std::nullopt;
    }
    case SchemaType::boolean:
      if (!parse_boolean(text)) return issue(DeckIssueKind::wrong_type);
      return std::nullopt;
    case SchemaType::choice:
      if (std::find(spec.choices.begin(), spec.choices.end(), text) == spec.choices.end()) {
        return issue(DeckIssueKind::not_in_choices, suggestion(text, spec.choices));
      }
      return std::nullopt;
    default:
      return std::nullopt;
  }
}

// Walks the deck and the schema together, collecting issues and filling in defaults.
class Validator {
 public:
  std::vector<DeckIssue> issues;

  void check(const Schema& schema, DeckNode& node) {
    const SchemaSpec& spec = schema.spec();
    switch (spec.type) {
      case SchemaType::map:
      case SchemaType::map_of:
        check_map(spec, node);
        return;
      case SchemaType::sequence:
        check_sequence(spec, node);
        return;
      default:
        if (std::optional<DeckIssue> problem = scalar_problem(spec, node)) {
          issues.push_back(std::move(*problem));
        }
    }
  }

 private:
  void check_map(const SchemaSpec& spec, DeckNode& node) {
    if (node.kind == DeckNodeKind::null) node.kind = DeckNodeKind::map;  // `hydro:` = all defaults
    if (node.kind != DeckNodeKind::map) {
      issues.push_back({DeckIssueKind::wrong_type, node.location, node.path, found_text(node),
                        expected_text(spec), ""});
      return;
    }
    for (DeckEntry& entry : node.entries) {
      if (spec.type == SchemaType::map_of) {
        check(*spec.element, entry.value);
      } else if (const SchemaField* field = find_field(spec, entry.key)) {
        check(field->schema, entry.value);
      } else {
        const std::vector<std::string> keys = field_keys(spec);
        issues.push_back({DeckIssueKind::unknown_key, entry.key_location, entry.value.path,
                          entry.key, join(keys), suggestion(entry.key, keys)});
      }
    }
    for (const SchemaField& field : spec.fields) {
      if (node.find(field.key)) continue;
      const SchemaSpec& field_spec = field.schema.spec();
      const std::string path = node.path.empty() ? field.key : node.path + "." + field.key;
      if (field_spec.presence == Presence::required) {
        issues.push_back({DeckIssueKind::missing_key, node.location, path, "nothing",
                          expected_text(field_spec), ""});
      } else if (field_spec.presence == Presence::defaulted) {
        DeckNode value{DeckNodeKind::scalar, path, node.location, field_spec.default_text, {}, {}};
        node.entries.push_back({field.key, node.location, std::move(value)});
      }
    }
  }

  void check_sequence(const SchemaSpec& spec, DeckNode& node) {
    if (node.kind == DeckNodeKind::null) node.kind = DeckNodeKind::sequence;  // `x:` = empty list
    if (node.kind != DeckNodeKind::sequence) {
      issues.push_back({DeckIssueKind::wrong_type, node.location, node.path, found_text(node),
                        expected_text(spec), ""});
      return;
    }
    const std::size_t count = node.items.size();
    if (count < spec.min_items || (spec.max_items && count > *spec.max_items)) {
      issues.push_back({DeckIssueKind::out_of_range, node.location, node.path,
                        fmt::format("{} item{}", count, count == 1 ? "" : "s"), expected_text(spec),
                        ""});
    }
    for (DeckNode& item : node.items) check(*spec.element, item);
  }
};

// ---- Schema building -----------------------------------------------------------------------

[[noreturn]] void misuse(const std::string& what) {
  throw std::logic_error("deck schema: " + what);
}

// The unit a key must end with: a number's own, or that of the numbers a sequence or a
// mapping of names holds (`heights_m: [10, 20]`).
std::string unit_of(const SchemaSpec& spec) {
  if (spec.element) return unit_of(spec.element->spec());
  return spec.unit;
}

void check_field(const SchemaField& field) {
  const SchemaSpec& spec = field.schema.spec();
  if (field.key.empty() || field.key.find_first_of(".[]") != std::string::npos) {
    misuse(fmt::format("key `{}` must be non-empty without '.', '[' or ']'", field.key));
  }
  if (field.key == "include") misuse("key `include` is reserved for including files");
  const std::string unit = unit_of(spec);
  if (!unit.empty() && !field.key.ends_with("_" + unit)) {
    misuse(
        fmt::format("key `{}` has unit \"{}\" but does not end in `_{}`; the key name says "
                    "the unit (e.g. `{}_{}`)",
                    field.key, unit, unit, field.key, unit));
  }
  if (spec.presence == Presence::defaulted) {
    DeckNode node;
    node.kind = DeckNodeKind::scalar;
    node.path = field.key;
    node.scalar = spec.default_text;
    if (std::optional<DeckIssue> problem = scalar_problem(spec, node)) {
      misuse(fmt::format("default {} of `{}` is not {}", spec.default_text, field.key,
                         problem->expected));
    }
  }
}

}  // namespace

Schema::Schema(SchemaType type) { spec_.type = type; }

Schema Schema::number() { return Schema(SchemaType::number); }
Schema Schema::integer() { return Schema(SchemaType::integer); }
Schema Schema::boolean() { return Schema(SchemaType::boolean); }
Schema Schema::string() { return Schema(SchemaType::string); }

Schema Schema::choice(std::vector<std::string> allowed) {
  if (allowed.empty()) misuse("a choice needs at least one allowed value");
  Schema schema(SchemaType::choice);
  schema.spec_.choices = std::move(allowed);
  return schema;
}

Schema Schema::map(std::vector<SchemaField> fields) {
  for (auto field = fields.begin(); field != fields.end(); ++field) {
    check_field(*field);
    if (std::any_of(fields.begin(), field, [&](const auto& f) { return f.key == field->key; })) {
      misuse(fmt::format("key `{}` declared twice", field->key));
    }
  }
  Schema schema(SchemaType::map);
  schema.spec_.fields = std::move(fields);
  return schema;
}

Schema Schema::map_of(Schema value) {
  Schema schema(SchemaType::map_of);
  schema.spec_.element = std::make_shared<const Schema>(std::move(value));
  return schema;
}

Schema Schema::sequence(Schema item) {
  Schema schema(SchemaType::sequence);
  schema.spec_.element = std::make_shared<const Schema>(std::move(item));
  return schema;
}

Schema Schema::optional() const {
  Schema copy = *this;
  copy.spec_.presence = Presence::optional;
  copy.spec_.default_text.clear();
  return copy;
}

Schema Schema::with_default(SchemaType value_type, std::string text) const {
  const bool fits = value_type == spec_.type ||
                    (value_type == SchemaType::integer && spec_.type == SchemaType::number) ||
                    (value_type == SchemaType::string && spec_.type == SchemaType::choice);
  if (!fits) misuse(fmt::format("default {} does not fit a {}", text, type_text(spec_)));
  Schema copy = *this;
  copy.spec_.presence = Presence::defaulted;
  copy.spec_.default_text = std::move(text);
  return copy;
}

// fmt's "{}" prints the shortest text that reads back to the same double.
Schema Schema::default_value(double value) const {
  return with_default(SchemaType::number, fmt::format("{}", value));
}
Schema Schema::default_value(int value) const {
  return default_value(static_cast<std::int64_t>(value));
}
Schema Schema::default_value(std::int64_t value) const {
  return with_default(SchemaType::integer, std::to_string(value));
}
Schema Schema::default_value(bool value) const {
  return with_default(SchemaType::boolean, value ? "true" : "false");
}
Schema Schema::default_value(const char* value) const {
  return with_default(SchemaType::string, value);
}
Schema Schema::default_value(const std::string& value) const {
  return with_default(SchemaType::string, value);
}

Schema Schema::with_bound(bool upper, double bound, bool inclusive) const {
  if (spec_.type != SchemaType::number && spec_.type != SchemaType::integer) {
    misuse(fmt::format("a range on a {}", type_text(spec_)));
  }
  Schema copy = *this;
  (upper ? copy.spec_.upper : copy.spec_.lower) = NumericBound{bound, inclusive};
  return copy;
}

Schema Schema::at_least(double bound) const { return with_bound(false, bound, true); }
Schema Schema::at_most(double bound) const { return with_bound(true, bound, true); }
Schema Schema::greater_than(double bound) const { return with_bound(false, bound, false); }
Schema Schema::less_than(double bound) const { return with_bound(true, bound, false); }

Schema Schema::min_items(std::size_t count) const {
  if (spec_.type != SchemaType::sequence) misuse("min_items on a " + type_text(spec_));
  Schema copy = *this;
  copy.spec_.min_items = count;
  return copy;
}

Schema Schema::max_items(std::size_t count) const {
  if (spec_.type != SchemaType::sequence) misuse("max_items on a " + type_text(spec_));
  Schema copy = *this;
  copy.spec_.max_items = count;
  return copy;
}

Schema Schema::unit(std::string key_suffix) const {
  if (spec_.type != SchemaType::number && spec_.type != SchemaType::integer) {
    misuse("a unit on a " + type_text(spec_));
  }
  const bool valid =
      !key_suffix.empty() && std::all_of(key_suffix.begin(), key_suffix.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
      });
  if (!valid) misuse("unit \"" + key_suffix + "\" must be a key suffix such as s, N_m, rad_s");
  Schema copy = *this;
  copy.spec_.unit = std::move(key_suffix);
  return copy;
}

Schema Schema::doc(std::string text) const {
  Schema copy = *this;
  copy.spec_.doc = std::move(text);
  return copy;
}

// ---- Validated deck ------------------------------------------------------------------------

struct ValidatedDeck::Shared {
  Schema schema;                             // schema the deck passed
  DeckNode root;                             // the deck with defaults filled in
  std::vector<std::filesystem::path> files;  // LoadedDeck::files
  std::string hash;                          // LoadedDeck::hash
};

struct ValidatedDeck::Resolved {
  const Schema* schema;  // declared schema at the path
  const DeckNode* node;  // value at the path; nullptr when absent from the deck
  std::string path;      // full key path from the deck root
};

ValidatedDeck::ValidatedDeck(std::shared_ptr<const Shared> shared, const Schema* schema,
                             const DeckNode* node)
    : shared_(std::move(shared)), schema_(schema), node_(node) {}

ValidatedDeck validate(const Schema& schema, LoadedDeck deck) {
  Validator validator;
  validator.check(schema, deck.root);
  if (!validator.issues.empty()) throw DeckError(std::move(validator.issues));
  auto shared = std::make_shared<const ValidatedDeck::Shared>(ValidatedDeck::Shared{
      schema, std::move(deck.root), std::move(deck.files), std::move(deck.hash)});
  return ValidatedDeck(shared, &shared->schema, &shared->root);
}

ValidatedDeck read_deck(const Schema& schema, const std::filesystem::path& file) {
  return validate(schema, load_deck(file));
}

// Follows `path` ("a.b[2].c") through the schema, which must declare every step, and through
// the deck, where the value may be absent.
ValidatedDeck::Resolved ValidatedDeck::resolve(std::string_view path) const {
  Resolved at{schema_, node_, node_->path};
  std::size_t i = 0;
  while (i < path.size()) {
    const SchemaSpec& spec = at.schema->spec();
    if (path[i] == '[') {
      const std::size_t close = path.find(']', i);
      const std::optional<std::int64_t> index =
          close == std::string_view::npos ? std::nullopt
                                          : parse_integer(path.substr(i + 1, close - i - 1));
      if (!index || *index < 0 || spec.type != SchemaType::sequence) {
        throw std::logic_error(fmt::format(
            "deck path `{}`: `{}` does not index a declared sequence", path, path.substr(i)));
      }
      const auto n = static_cast<std::size_t>(*index);
      at.path += fmt::format("[{}]", n);
      at.schema = spec.element.get();
      at.node = at.node && n < at.node->items.size() ? &at.node->items[n] : nullptr;
      i = close + 1;
    } else {
      const std::size_t end = std::min(path.find_first_of(".[", i), path.size());
      const std::string_view key = path.substr(i, end - i);
      const SchemaField* field = spec.type == SchemaType::map ? find_field(spec, key) : nullptr;
      if (field == nullptr && spec.type != SchemaType::map_of) {
        throw std::logic_error(
            fmt::format("deck path `{}`: key `{}` is not declared in the schema", path, key));
      }
      if (!at.path.empty()) at.path += '.';
      at.path += key;
      at.schema = field ? &field->schema : spec.element.get();
      at.node = at.node ? at.node->find(key) : nullptr;
      i = end;
    }
    if (i < path.size() && path[i] == '.') ++i;
  }
  return at;
}

// The value at `path`, which must be declared as `type` and present.
const DeckNode& ValidatedDeck::value(std::string_view path, SchemaType type,
                                     const char* reader) const {
  const Resolved at = resolve(path);
  const SchemaSpec& spec = at.schema->spec();
  const bool fits = spec.type == type ||
                    (type == SchemaType::string && spec.type == SchemaType::choice) ||
                    (type == SchemaType::map && spec.type == SchemaType::map_of);
  if (!fits) {
    throw std::logic_error(fmt::format("deck path `{}` is declared as {} but read with {}()",
                                       at.path, type_text(spec), reader));
  }
  if (at.node == nullptr) {
    throw std::logic_error(
        fmt::format("deck path `{}` is absent from the deck; check has() "
                    "before {}()",
                    at.path, reader));
  }
  return *at.node;
}

bool ValidatedDeck::has(std::string_view path) const { return resolve(path).node != nullptr; }

double ValidatedDeck::number(std::string_view path) const {
  return *parse_number(value(path, SchemaType::number, "number").scalar);
}

std::int64_t ValidatedDeck::integer(std::string_view path) const {
  return *parse_integer(value(path, SchemaType::integer, "integer").scalar);
}

bool ValidatedDeck::boolean(std::string_view path) const {
  return *parse_boolean(value(path, SchemaType::boolean, "boolean").scalar);
}

std::string ValidatedDeck::string(std::string_view path) const {
  return value(path, SchemaType::string, "string").scalar;
}

// The items of the sequence at `path`, whose items must be declared as `type`.
const std::vector<DeckNode>& ValidatedDeck::items(std::string_view path, SchemaType type,
                                                  const char* reader) const {
  const DeckNode& list = value(path, SchemaType::sequence, reader);
  const SchemaSpec& item = resolve(path).schema->spec().element->spec();
  if (item.type != type && !(type == SchemaType::string && item.type == SchemaType::choice)) {
    throw std::logic_error(
        fmt::format("deck path `{}` holds items declared as {} but is read "
                    "with {}()",
                    list.path, type_text(item), reader));
  }
  return list.items;
}

std::vector<double> ValidatedDeck::numbers(std::string_view path) const {
  std::vector<double> values;
  for (const DeckNode& item : items(path, SchemaType::number, "numbers")) {
    values.push_back(*parse_number(item.scalar));
  }
  return values;
}

std::vector<std::string> ValidatedDeck::strings(std::string_view path) const {
  std::vector<std::string> values;
  for (const DeckNode& item : items(path, SchemaType::string, "strings")) {
    values.push_back(item.scalar);
  }
  return values;
}

std::size_t ValidatedDeck::size(std::string_view path) const {
  return value(path, SchemaType::sequence, "size").items.size();
}

std::vector<std::string> ValidatedDeck::keys(std::string_view path) const {
  std::vector<std::string> keys;
  for (const DeckEntry& entry : value(path, SchemaType::map, "keys").entries) {
    keys.push_back(entry.key);
  }
  return keys;
}

ValidatedDeck ValidatedDeck::section(std::string_view path) const {
  const Resolved at = resolve(path);
  if (at.node == nullptr) {
    throw std::logic_error(
        fmt::format("deck path `{}` is absent from the deck; check has() "
                    "before section()",
                    at.path));
  }
  return ValidatedDeck(shared_, at.schema, at.node);
}

SourceLocation ValidatedDeck::location(std::string_view path) const {
  const Resolved at = resolve(path);
  if (at.node == nullptr) {
    throw std::logic_error(
        fmt::format("deck path `{}` is absent from the deck; check has() "
                    "before location()",
                    at.path));
  }
  return at.node->location;
}

const std::string& ValidatedDeck::path() const { return node_->path; }
const std::vector<std::filesystem::path>& ValidatedDeck::files() const { return shared_->files; }
const std::string& ValidatedDeck::hash() const { return shared_->hash; }

// ---- Documentation -------------------------------------------------------------------------

namespace {

// One entry per declared key below `schema`; the items of sequences and the values of
// mappings of names are described through their keys, as `lines[].length_m`, `lines.<name>.x`.
void describe(const Schema& schema, const std::string& path, std::string& text) {
  const SchemaSpec& spec = schema.spec();
  if (spec.type == SchemaType::map_of) describe(*spec.element, path + ".<name>", text);
  if (spec.type == SchemaType::sequence) describe(*spec.element, path + "[]", text);
  for (const SchemaField& field : spec.fields) {
    const SchemaSpec& field_spec = field.schema.spec();
    const std::string field_path = path.empty() ? field.key : path + "." + field.key;
    const std::string presence = field_spec.presence == Presence::required ? "required"
                                 : field_spec.presence == Presence::optional
                                     ? "optional"
                                     : "default " + field_spec.default_text;
    text += fmt::format("{}: {}, {}\n", field_path, type_text(field_spec), presence);
    if (!field_spec.doc.empty()) text += "    " + field_spec.doc + "\n";
    describe(field.schema, field_path, text);
  }
}

}  // namespace

std::string describe_schema(const Schema& schema) {
  std::string text;
  describe(schema, "", text);
  return text;
}

}  // namespace fowtsim::io
