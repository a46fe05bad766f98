#pragma once
// Private helpers shared by the schema sources: scalar parsing, the text of a schema node, the
// field lookup and scalar check of validation, and the deck a ValidatedDeck shares.
#include <charconv>
#include <cmath>
#include <system_error>

#include "fowtsim/io/schema.hpp"

namespace fowtsim::io {
namespace detail {

// ---- Scalar parsing: one definition shared by validation, defaults and typed reads ----------

inline std::optional<double> parse_number(std::string_view text) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

inline std::optional<std::int64_t> parse_integer(std::string_view text) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-') text.remove_prefix(1);
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// YAML 1.2 core booleans only: `yes`/`on` are YAML 1.1 and too easy to write by accident.
inline std::optional<bool> parse_boolean(std::string_view text) {
  if (text == "true" || text == "True" || text == "TRUE") return true;
  if (text == "false" || text == "False" || text == "FALSE") return false;
  return std::nullopt;
}

// ---- Text for messages and documentation (schema_describe.cpp) -----------------------------

std::string join(const std::vector<std::string>& words);

// The type with its constraints, without an article: "number > 0 [s]", "one of a, b".
std::string type_text(const SchemaSpec& spec);

// ---- Validation (schema_validate.cpp) ------------------------------------------------------

const SchemaField* find_field(const SchemaSpec& spec, std::string_view key);

// The problem with a scalar value, if any (number, integer, boolean, string, choice).
std::optional<DeckIssue> scalar_problem(const SchemaSpec& spec, const DeckNode& node);

}  // namespace detail

struct ValidatedDeck::Shared {
  Schema schema;                             // schema the deck passed
  DeckNode root;                             // the deck with defaults filled in
  std::vector<std::filesystem::path> files;  // LoadedDeck::files
  std::string hash;                          // LoadedDeck::hash
};

}  // namespace fowtsim::io
