#include "fowtsim/io/schema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "schema_internal.hpp"

namespace fowtsim::io {

// ---- Validated deck ------------------------------------------------------------------------

struct ValidatedDeck::Resolved {
  const Schema* schema;  // declared schema at the path
  const DeckNode* node;  // value at the path; nullptr when absent from the deck
  std::string path;      // full key path from the deck root
};

ValidatedDeck::ValidatedDeck(std::shared_ptr<const Shared> shared, const Schema* schema,
                             const DeckNode* node)
    : shared_(std::move(shared)), schema_(schema), node_(node) {}

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
          close == std::string_view::npos
              ? std::nullopt
              : detail::parse_integer(path.substr(i + 1, close - i - 1));
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
      const SchemaField* field =
          spec.type == SchemaType::map ? detail::find_field(spec, key) : nullptr;
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
                                       at.path, detail::type_text(spec), reader));
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
  return *detail::parse_number(value(path, SchemaType::number, "number").scalar);
}

std::int64_t ValidatedDeck::integer(std::string_view path) const {
  return *detail::parse_integer(value(path, SchemaType::integer, "integer").scalar);
}

bool ValidatedDeck::boolean(std::string_view path) const {
  return *detail::parse_boolean(value(path, SchemaType::boolean, "boolean").scalar);
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
                    list.path, detail::type_text(item), reader));
  }
  return list.items;
}

std::vector<double> ValidatedDeck::numbers(std::string_view path) const {
  std::vector<double> values;
  for (const DeckNode& item : items(path, SchemaType::number, "numbers")) {
    values.push_back(*detail::parse_number(item.scalar));
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

namespace {

// Reading an absent (optional, left out) path is a programming error: the caller checks has().
void require_present(const DeckNode* node, const std::string& path, const char* reader) {
  if (node == nullptr) {
    throw std::logic_error(
        fmt::format("deck path `{}` is absent from the deck; check has() before {}()", path, reader));
  }
}

}  // namespace

ValidatedDeck ValidatedDeck::section(std::string_view path) const {
  const Resolved at = resolve(path);
  require_present(at.node, at.path, "section");
  return ValidatedDeck(shared_, at.schema, at.node);
}

SourceLocation ValidatedDeck::location(std::string_view path) const {
  const Resolved at = resolve(path);
  require_present(at.node, at.path, "location");
  return at.node->location;
}

const std::string& ValidatedDeck::path() const { return node_->path; }
const std::vector<std::filesystem::path>& ValidatedDeck::files() const { return shared_->files; }
const std::string& ValidatedDeck::hash() const { return shared_->hash; }

}  // namespace fowtsim::io
