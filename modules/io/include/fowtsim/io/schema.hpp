#pragma once
// Deck schemas (DESIGN.md §5): the keys a deck may hold, with type, range, unit, default and
// documentation, declared in C++ next to the code that reads them. validate() checks a loaded
// deck against a schema and reports every problem at once; ValidatedDeck then reads typed values
// with the defaults filled in.
//
// The unit rule, one for the whole project: the key name says the unit. A number declared with
// .unit("s") must sit under a key ending in "_s" (`dt_coupling_s`, `mass_kg`, `stiffness_N_m`,
// `rotor_speed_rpm`, `angle_deg`); deck values are plain numbers. Dimensionless numbers have no
// unit. Schema::map enforces the rule when the schema is built.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fowtsim/io/deck.hpp"

namespace fowtsim::io {

class Schema;
struct SchemaField;

enum class SchemaType { number, integer, boolean, string, choice, map, map_of, sequence };

// When a key may be left out of its mapping.
enum class Presence { required, optional, defaulted };

struct NumericBound {
  double value = 0.0;     // the limit, in the unit of the field
  bool inclusive = true;  // true for >= / <=, false for > / <
};

struct SchemaSpec {
  SchemaType type = SchemaType::string;    // kind of value
  Presence presence = Presence::required;  // whether the key may be absent from its mapping
  std::string default_text;                // default as YAML text, e.g. "10"; set iff defaulted
  std::optional<NumericBound> lower;       // lower limit (number, integer); none = unbounded
  std::optional<NumericBound> upper;       // upper limit (number, integer); none = unbounded
  std::string unit;                  // unit as the key suffix spells it ("s", "N_m"); "" = none
  std::string doc;                   // one-line meaning, for the deck documentation
  std::vector<std::string> choices;  // allowed values (choice)
  std::vector<SchemaField> fields;   // declared keys in documentation order (map)
  std::shared_ptr<const Schema> element;  // item schema (sequence), value schema (map_of)
  std::size_t min_items = 0;              // fewest items (sequence)
  std::optional<std::size_t> max_items;   // most items (sequence); none = unbounded
};

// A schema node, built with a fluent API; every modifier returns a modified copy:
//   Schema::map({{"t_max_s", Schema::number().unit("s").greater_than(0.0).doc("...")},
//                {"substeps", Schema::integer().at_least(1).default_value(10)}})
// Misuse (a modifier that does not fit the type, a default outside the range, a unit that is not
// the key's suffix) throws std::logic_error: schemas are code, not input.
class Schema {
 public:
  static Schema number();   // a double
  static Schema integer();  // a 64-bit integer
  static Schema boolean();  // true or false
  static Schema string();   // any scalar text
  static Schema choice(std::vector<std::string> allowed);
  static Schema map(std::vector<SchemaField> fields);  // a mapping with exactly these keys
  static Schema map_of(Schema value);  // a mapping with free keys (names), each value `value`
  static Schema sequence(Schema item);

  [[nodiscard]] Schema optional() const;
  [[nodiscard]] Schema default_value(double value) const;
  [[nodiscard]] Schema default_value(int value) const;
  [[nodiscard]] Schema default_value(std::int64_t value) const;
  [[nodiscard]] Schema default_value(bool value) const;
  [[nodiscard]] Schema default_value(const char* value) const;
  [[nodiscard]] Schema default_value(const std::string& value) const;
  [[nodiscard]] Schema at_least(double bound) const;
  [[nodiscard]] Schema at_most(double bound) const;
  [[nodiscard]] Schema greater_than(double bound) const;
  [[nodiscard]] Schema less_than(double bound) const;
  [[nodiscard]] Schema min_items(std::size_t count) const;
  [[nodiscard]] Schema max_items(std::size_t count) const;
  [[nodiscard]] Schema unit(std::string key_suffix) const;
  [[nodiscard]] Schema doc(std::string text) const;

  const SchemaSpec& spec() const { return spec_; }

 private:
  explicit Schema(SchemaType type);
  Schema with_default(SchemaType value_type, std::string text) const;
  Schema with_bound(bool upper, double bound, bool inclusive) const;

  SchemaSpec spec_;
};

struct SchemaField {
  std::string key;  // key in the mapping; a number with a unit must end in "_" + unit
  Schema schema;    // what its value must be
};

// A deck that passed validation. Reads take a key path relative to this section, e.g.
// "simulation.t_max_s", "lines[0].length_m" ("" is the section itself); defaults are filled in.
// Reading a path the schema does not declare, with the wrong type, or that is absent (an
// optional key left out) is a programming error and throws std::logic_error. Copies are cheap
// and share the deck.
class ValidatedDeck {
 public:
  bool has(std::string_view path) const;
  double number(std::string_view path) const;
  std::int64_t integer(std::string_view path) const;
  bool boolean(std::string_view path) const;
  std::string string(std::string_view path) const;                // a string or a choice
  std::vector<double> numbers(std::string_view path) const;       // a sequence of numbers
  std::vector<std::string> strings(std::string_view path) const;  // a sequence of strings
  std::size_t size(std::string_view path) const;                  // items of a sequence
  std::vector<std::string> keys(std::string_view path) const;     // keys present in a mapping

  // A view rooted at `path`, so a module can read its own part with short paths.
  ValidatedDeck section(std::string_view path) const;
  // Where the value is written; for a default, the mapping it was filled into.
  SourceLocation location(std::string_view path) const;

  const std::string& path() const;  // key path of this section in the deck; "" at the top
  const std::vector<std::filesystem::path>& files() const;  // files read (LoadedDeck::files)
  const std::string& hash() const;                          // deck hash (LoadedDeck::hash)

 private:
  struct Shared;
  struct Resolved;
  friend ValidatedDeck validate(const Schema& schema, LoadedDeck deck);

  ValidatedDeck(std::shared_ptr<const Shared> shared, const Schema* schema, const DeckNode* node);
  Resolved resolve(std::string_view path) const;
  const DeckNode& value(std::string_view path, SchemaType type, const char* reader) const;
  const std::vector<DeckNode>& items(std::string_view path, SchemaType type,
                                     const char* reader) const;

  std::shared_ptr<const Shared> shared_;  // the whole deck and its schema
  const Schema* schema_;                  // schema of this section, inside shared_
  const DeckNode* node_;                  // node of this section, inside shared_
};

// Checks `deck` against `schema`, collecting every unknown key, missing key, wrong type,
// out-of-range value and bad choice; throws one DeckError listing them all.
ValidatedDeck validate(const Schema& schema, LoadedDeck deck);

// load_deck, apply_settings (the command line's --set) then validate: the usual way to read a scene.
ValidatedDeck read_deck(const Schema& schema, const std::filesystem::path& file,
                        const std::vector<std::string>& settings = {});

// The schema as documentation, one entry per key path: type with range and unit, whether it is
// required, optional or its default, and its doc line (for `fowtsim --help-deck`).
std::string describe_schema(const Schema& schema);

}  // namespace fowtsim::io
