#include "fowtsim/io/schema.hpp"

#include <fmt/format.h>

#include "schema_internal.hpp"

namespace fowtsim::io {

// ---- Text for messages and documentation ---------------------------------------------------

namespace {

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

}  // namespace

std::string detail::join(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& word : words) text += (text.empty() ? "" : ", ") + word;
  return text;
}

std::string detail::type_text(const SchemaSpec& spec) {
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
    text += fmt::format("{}: {}, {}\n", field_path, detail::type_text(field_spec), presence);
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
