#pragma once
// Field lists of plain state structs: each struct that changes during a run names its fields once,
//
//   template <class Archive> void fields(Archive& a, T& s) { a.io(s.x, s.y); a.scratch(s.w); }
//
// (found by argument-dependent lookup, beside the struct), and that one list serves checkpoints,
// comparison (two states are the same when their fields write the same bytes) and a count:
// `listed_field_count<T>()` must equal `member_count<T>()`, so a field added to a struct and not to
// its list fails a test (driver/tests/scene_state_tests.cpp). `scratch` names workspace that every
// call overwrites before reading it: it is counted but not written.
#include <cstddef>

namespace fowtsim {

namespace detail {
struct AnyField {
  template <class T>
  operator T() const;  // never defined: only asked whether it could initialise a member
};
template <class T, class... A>
consteval std::size_t count_members(A... a) {
  if constexpr (requires { T{a..., AnyField{}}; }) return count_members<T>(a..., AnyField{});
  else return sizeof...(A);
}
}  // namespace detail

// The number of members of an aggregate struct (how many initialisers its braces take).
template <class T>
consteval std::size_t member_count() {
  return detail::count_members<T>();
}

// An archive that counts the fields a list names, one level deep.
struct FieldCounter {
  std::size_t count = 0;
  template <class... T>
  void io(T&...) {
    count += sizeof...(T);
  }
  template <class... T>
  void scratch(T&...) {
    count += sizeof...(T);
  }
};

template <class T>
std::size_t listed_field_count() {
  T value{};
  FieldCounter counter;
  fields(counter, value);
  return counter.count;
}

}  // namespace fowtsim
