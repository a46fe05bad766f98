#pragma once
// Small helpers shared by the deck-section readers: fixed-length vectors and matrices, files named
// relative to the deck, and the "file:line:col: key" prefix of a message about a value that passed
// the schema but not a module's own validation.
#include <filesystem>
#include <string>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/types.hpp"
#include "fowtsim/io/schema.hpp"

namespace fowtsim::driver {

// A sequence of exactly n numbers; the unit is in the key name.
io::Schema number_vector(std::size_t n, const char* doc);
// A 6×6 matrix written as 36 numbers, row by row.
io::Schema matrix6(const char* doc);

Vec3 vec3(const io::ValidatedDeck& deck, const std::string& path);
Vec6 vec6(const io::ValidatedDeck& deck, const std::string& path);
Mat6 mat6(const io::ValidatedDeck& deck, const std::string& path);

// The file a string key names: a relative path is taken from the directory of the deck file that
// holds the key (decks include one another).
std::filesystem::path beside_deck(const io::ValidatedDeck& deck, const std::string& key);
// The same for a key that names a file to read: a directory or a missing path stops at the key's
// file:line ("… is a directory, not a file"), not later as an unreadable or empty file.
std::filesystem::path file_beside_deck(const io::ValidatedDeck& deck, const std::string& key);

// "file:line:col: path" of a value in the deck.
std::string where(const io::ValidatedDeck& deck, const std::string& path);

// A module's own validation failed on values the schema let through: re-throw its InputError
// prefixed with the file:line of the deck section (the message names the keys).
[[noreturn]] void rethrow_located(const io::ValidatedDeck& section, const InputError& error);

// Runs `check` (a module's validation, or a construction that validates) and returns its result,
// re-throwing its InputError located at `section` as rethrow_located does.
template <class Check>
decltype(auto) located(const io::ValidatedDeck& section, Check&& check) {
  try {
    return check();
  } catch (const InputError& e) {
    rethrow_located(section, e);
  }
}

}  // namespace fowtsim::driver
