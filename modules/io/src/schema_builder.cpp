#include "fowtsim/io/schema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "schema_internal.hpp"

namespace fowtsim::io {
namespace {

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
    if (std::optional<DeckIssue> problem = detail::scalar_problem(spec, node)) {
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
  if (!fits) misuse(fmt::format("default {} does not fit a {}", text, detail::type_text(spec_)));
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
    misuse(fmt::format("a range on a {}", detail::type_text(spec_)));
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
  if (spec_.type != SchemaType::sequence) misuse("min_items on a " + detail::type_text(spec_));
  Schema copy = *this;
  copy.spec_.min_items = count;
  return copy;
}

Schema Schema::max_items(std::size_t count) const {
  if (spec_.type != SchemaType::sequence) misuse("max_items on a " + detail::type_text(spec_));
  Schema copy = *this;
  copy.spec_.max_items = count;
  return copy;
}

Schema Schema::unit(std::string key_suffix) const {
  if (spec_.type != SchemaType::number && spec_.type != SchemaType::integer) {
    misuse("a unit on a " + detail::type_text(spec_));
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

}  // namespace fowtsim::io
