#pragma once
// One declaration per deck key: its name, its schema (type, unit, range, default, help text) and
// the Params field it fills, in one place, so that validation, `--help-deck` (both from schema())
// and the reader (read_into()) cannot disagree on a key:
//
//   DeckSection<mooring::MooringParams>()
//       .key("depth_m", Schema::number().greater_than(0.0).doc("water depth"), &MooringParams::depth_m)
//       .section("solver", solver_section(), &MooringParams::solver, true, "catenary solver settings")
//       .list("lines", line_section(), &MooringParams::lines, 1, "mooring lines")
//
// A key without a default that the deck leaves out (an optional key) leaves its field as it is.
// Binding a schema to a field of another type is a programming error (std::logic_error).
#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "fowtsim/io/schema.hpp"

namespace fowtsim::driver {

template <class P>
class DeckSection {
 public:
  // A scalar key filling the field std::invoke(field, p) names: a member pointer (of P or of a base
  // of P) or an accessor returning a reference (an array element, a nested member). Types: double
  // (number), int or std::uint64_t (integer), bool (boolean), std::string (string or choice), Vec3,
  // Vec6, Mat6 (36 numbers, row by row), std::vector<double>, std::array<double, N> (sequences of
  // numbers), std::vector of any of these (a sequence of them), std::optional of any (an optional key).
  template <class Field>
  DeckSection& key(std::string name, io::Schema schema, Field field) {
    using T = std::remove_cvref_t<std::invoke_result_t<Field, P&>>;
    check_type<T>(name, schema);
    add(std::move(name), std::move(schema), [field](const io::ValidatedDeck& d, const std::string& k, P& p) {
      std::invoke(field, p) = value<T>(d, k);
    });
    return *this;
  }
  // A key whose value fills the field through convert: convert(text) for a choice naming an enum,
  // convert(number) for a number in other units than the field's (degrees → radians).
  template <class Field, class Convert>
  DeckSection& key(std::string name, io::Schema schema, Field field, Convert convert) {
    using From = std::conditional_t<std::is_invocable_v<Convert, std::string>, std::string, double>;
    check_type<From>(name, schema);
    add(std::move(name), std::move(schema), [field, convert](const io::ValidatedDeck& d, const std::string& k, P& p) {
      std::invoke(field, p) = convert(value<From>(d, k));
    });
    return *this;
  }
  // A key whose reading needs more than its value (a path relative to the deck file): read(d, key, p).
  template <class Read>
  DeckSection& custom(std::string name, io::Schema schema, Read read) {
    add(std::move(name), std::move(schema), std::move(read));
    return *this;
  }
  // A nested mapping read into the field (named as for key()). optional: absent leaves the field's
  // defaults, or an empty std::optional<Q>.
  template <class Q, class Field>
  DeckSection& section(std::string name, const DeckSection<Q>& sub, Field field, bool optional, std::string doc) {
    const io::Schema schema = sub.schema().doc(std::move(doc));
    add(std::move(name), optional ? schema.optional() : schema,
        [sub, field](const io::ValidatedDeck& d, const std::string& k, P& p) {
          auto& target = std::invoke(field, p);
          if constexpr (std::is_same_v<std::remove_reference_t<decltype(target)>, std::optional<Q>>)
            sub.read_into(d.section(k), target.emplace());
          else
            sub.read_into(d.section(k), target);
        });
    return *this;
  }
  // A sequence of mappings, each read into one element of the std::vector<Q> field (named as for
  // key()); an optional key when the field is a std::optional<std::vector<Q>>.
  template <class Q, class Field>
  DeckSection& list(std::string name, const DeckSection<Q>& item, Field field, std::size_t min_items, std::string doc) {
    constexpr bool optional = is_optional<std::remove_cvref_t<std::invoke_result_t<Field, P&>>>::value;
    const io::Schema schema = io::Schema::sequence(item.schema()).min_items(min_items).doc(std::move(doc));
    add(std::move(name), optional ? schema.optional() : schema,
        [item, field](const io::ValidatedDeck& d, const std::string& k, P& p) {
          auto& f = std::invoke(field, p);
          std::vector<Q>& target = [&]() -> std::vector<Q>& {
            if constexpr (optional)
              return f.emplace();
            else
              return f;
          }();
          target.clear();
          for (std::size_t i = 0; i < d.size(k); ++i) {
            Q q{};
            item.read_into(d.section(fmt::format("{}[{}]", k, i)), q);
            target.push_back(q);
          }
        });
    return *this;
  }
  // The keys of `base`, a section of a base class of P, here in their order (a section that has
  // the keys of another and more).
  template <class Q>
    requires std::is_base_of_v<Q, P>
  DeckSection& keys_of(const DeckSection<Q>& base) {
    for (std::size_t i = 0; i < base.fields_.size(); ++i)
      add(base.fields_[i].key, base.fields_[i].schema,
          [read = base.readers_[i]](const io::ValidatedDeck& d, const std::string& k, P& p) { read(d, k, p); });
    return *this;
  }

  io::Schema schema() const { return io::Schema::map(fields_); }
  // Every declared key the deck holds (or defaults) into p.
  void read_into(const io::ValidatedDeck& d, P& p) const {
    for (std::size_t i = 0; i < fields_.size(); ++i)
      if (d.has(fields_[i].key)) readers_[i](d, fields_[i].key, p);
  }
  // A P with its own defaults, then every declared key the deck holds.
  P read(const io::ValidatedDeck& d) const {
    P p{};
    read_into(d, p);
    return p;
  }

 private:
  template <class>
  friend class DeckSection;
  using Reader = std::function<void(const io::ValidatedDeck&, const std::string&, P&)>;
  void add(std::string name, io::Schema schema, Reader reader) {
    fields_.push_back({std::move(name), std::move(schema)});
    readers_.push_back(std::move(reader));
  }
  template <class T>
  struct is_optional : std::false_type {};
  template <class T>
  struct is_optional<std::optional<T>> : std::true_type {};
  template <class T>
  struct is_vector : std::false_type {};
  template <class T>
  struct is_vector<std::vector<T>> : std::true_type {};
  template <class T>
  struct is_array : std::false_type {};
  template <std::size_t N>
  struct is_array<std::array<double, N>> : std::true_type {};

  template <class T>
  static T value(const io::ValidatedDeck& d, const std::string& k) {
    if constexpr (is_optional<T>::value) return value<typename T::value_type>(d, k);
    else if constexpr (std::is_same_v<T, double>) return d.number(k);
    else if constexpr (std::is_same_v<T, int>) {
      // The schema's integers are 64-bit: one read into an int must not wrap (decimation 2^32 → 0).
      const std::int64_t n = d.integer(k);
      if (n < std::numeric_limits<int>::min() || n > std::numeric_limits<int>::max())
        throw InputError({"deck", std::nullopt, k, fmt::format("at most {}", std::numeric_limits<int>::max())},
                         where(d, k) + fmt::format(": {} is out of range", n));
      return static_cast<int>(n);
    }
    else if constexpr (std::is_same_v<T, std::uint64_t>) return static_cast<std::uint64_t>(d.integer(k));
    else if constexpr (std::is_same_v<T, bool>) return d.boolean(k);
    else if constexpr (std::is_same_v<T, std::string>) return d.string(k);
    else if constexpr (std::is_same_v<T, std::vector<double>>) return d.numbers(k);
    else if constexpr (is_array<T>::value) {
      const std::vector<double> v = d.numbers(k);
      T out;
      std::copy_n(v.begin(), out.size(), out.begin());
      return out;
    } else if constexpr (is_vector<T>::value) {
      T out;
      for (std::size_t i = 0; i < d.size(k); ++i) out.push_back(value<typename T::value_type>(d, fmt::format("{}[{}]", k, i)));
      return out;
    } else if constexpr (std::is_same_v<T, Vec6>) return vec6(d, k);
    else if constexpr (std::is_same_v<T, Mat6>) return mat6(d, k);
    else return vec3(d, k);
  }
  template <class T>
  static void check_type(const std::string& name, const io::Schema& schema) {
    using io::SchemaType;
    const io::SchemaSpec& spec = schema.spec();
    if constexpr (is_optional<T>::value) {
      check_type<typename T::value_type>(name, schema);
    } else if constexpr (is_vector<T>::value && !std::is_same_v<T, std::vector<double>>) {
      if (spec.type != SchemaType::sequence) type_error(name);
      check_type<typename T::value_type>(name, *spec.element);
    } else {
      const SchemaType t = spec.type;
      const bool ok = std::is_same_v<T, double>        ? t == SchemaType::number
                      : std::is_same_v<T, int> || std::is_same_v<T, std::uint64_t> ? t == SchemaType::integer
                      : std::is_same_v<T, bool>        ? t == SchemaType::boolean
                      : std::is_same_v<T, std::string> ? (t == SchemaType::string || t == SchemaType::choice)
                      : std::is_same_v<T, Vec3> || std::is_same_v<T, Vec6> || std::is_same_v<T, Mat6> ||
                              std::is_same_v<T, std::vector<double>> || is_array<T>::value
                          ? t == SchemaType::sequence
                          : false;
      if (!ok) type_error(name);
    }
  }
  [[noreturn]] static void type_error(const std::string& name) {
    throw std::logic_error("deck key " + name + ": its schema's type does not fit the field it fills");
  }

  std::vector<io::SchemaField> fields_;
  std::vector<Reader> readers_;
};

}  // namespace fowtsim::driver
