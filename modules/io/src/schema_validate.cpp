#include "fowtsim/io/schema.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "fowtsim/io/suggest.hpp"
#include "schema_internal.hpp"

namespace fowtsim::io {
namespace {

// ---- Text for messages ---------------------------------------------------------------------

// What a value must be, as a message says it: "a number > 0 [s]", "an integer >= 1".
std::string expected_text(const SchemaSpec& spec) {
  switch (spec.type) {
    case SchemaType::boolean:
      return "true or false";
    case SchemaType::choice:
      return detail::type_text(spec);
    case SchemaType::integer:
      return "an " + detail::type_text(spec);
    default:
      return "a " + detail::type_text(spec);
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

// "did you mean `x`?" for the closest candidate (io/suggest.hpp).
std::string suggestion(std::string_view written, const std::vector<std::string>& candidates) {
  return did_you_mean(written, candidates);
}

// For "12.1 rpm" where a number is expected: the unit belongs in the key name, not the value.
std::string unit_in_value_hint(const SchemaSpec& spec, const std::string& text) {
  const std::size_t space = text.find_first_of(" \t");
  if (space == std::string::npos || !detail::parse_number(text.substr(0, space))) return "";
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

bool in_range(const SchemaSpec& spec, double value) {
  if (spec.lower &&
      (spec.lower->inclusive ? value < spec.lower->value : value <= spec.lower->value)) {
    return false;
  }
  return !(spec.upper &&
           (spec.upper->inclusive ? value > spec.upper->value : value >= spec.upper->value));
}

}  // namespace

const SchemaField* detail::find_field(const SchemaSpec& spec, std::string_view key) {
  for (const SchemaField& field : spec.fields) {
    if (field.key == key) return &field;
  }
  return nullptr;
}

std::optional<DeckIssue> detail::scalar_problem(const SchemaSpec& spec, const DeckNode& node) {
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

namespace {

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
        if (std::optional<DeckIssue> problem = detail::scalar_problem(spec, node)) {
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
      } else if (const SchemaField* field = detail::find_field(spec, entry.key)) {
        check(field->schema, entry.value);
      } else {
        const std::vector<std::string> keys = field_keys(spec);
        issues.push_back({DeckIssueKind::unknown_key, entry.key_location, entry.value.path,
                          entry.key, detail::join(keys), suggestion(entry.key, keys)});
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

}  // namespace

ValidatedDeck validate(const Schema& schema, LoadedDeck deck) {
  Validator validator;
  validator.check(schema, deck.root);
  if (!validator.issues.empty()) throw DeckError(std::move(validator.issues));
  auto shared = std::make_shared<const ValidatedDeck::Shared>(ValidatedDeck::Shared{
      schema, std::move(deck.root), std::move(deck.files), std::move(deck.hash)});
  return ValidatedDeck(shared, &shared->schema, &shared->root);
}

ValidatedDeck read_deck(const Schema& schema, const std::filesystem::path& file, const std::vector<std::string>& settings) {
  LoadedDeck deck = load_deck(file);
  apply_settings(deck, settings);
  return validate(schema, std::move(deck));
}

}  // namespace fowtsim::io
