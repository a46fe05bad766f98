#include "decks/deck_helpers.hpp"

#include <fmt/format.h>

namespace fowtsim::driver {

io::Schema number_vector(std::size_t n, const char* doc) {
  return io::Schema::sequence(io::Schema::number()).min_items(n).max_items(n).doc(doc);
}

io::Schema matrix6(const char* doc) { return number_vector(36, doc); }

Vec3 vec3(const io::ValidatedDeck& deck, const std::string& path) {
  const std::vector<double> v = deck.numbers(path);
  return Vec3(v[0], v[1], v[2]);
}

Vec6 vec6(const io::ValidatedDeck& deck, const std::string& path) {
  const std::vector<double> v = deck.numbers(path);
  Vec6 out;
  for (int i = 0; i < 6; ++i) out[i] = v[i];
  return out;
}

Mat6 mat6(const io::ValidatedDeck& deck, const std::string& path) {
  Mat6 m;
  const std::vector<double> v = deck.numbers(path);
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) m(r, c) = v[6 * r + c];
  return m;
}

std::filesystem::path beside_deck(const io::ValidatedDeck& deck, const std::string& key) {
  const std::filesystem::path file = deck.string(key);
  return file.is_absolute() ? file : std::filesystem::path(deck.location(key).file).parent_path() / file;
}

std::filesystem::path file_beside_deck(const io::ValidatedDeck& deck, const std::string& key) {
  const std::filesystem::path file = beside_deck(deck, key);
  std::error_code error;
  const std::filesystem::file_type type = std::filesystem::status(file, error).type();
  if (type == std::filesystem::file_type::regular) return file;
  const char* found = type == std::filesystem::file_type::directory   ? "is a directory, not a file"
                      : type == std::filesystem::file_type::not_found ? "does not exist"
                                                                      : "is not a regular file";
  throw InputError({"deck", std::nullopt, key, "a file (relative paths are taken from the deck file's directory)"},
                   fmt::format("{}: {} {}", where(deck, key), file.string(), found));
}

std::string where(const io::ValidatedDeck& deck, const std::string& path) {
  const io::SourceLocation loc = deck.location(path);
  const std::string full = deck.path().empty() ? path : deck.path() + "." + path;
  return fmt::format("{}: {}", loc.to_string(), full);  // a --set value has no line: just its name
}

void rethrow_located(const io::ValidatedDeck& section, const InputError& error) {
  const io::SourceLocation loc = section.location("");
  throw InputError(error.context(),
                   fmt::format("{}:{}:{}: {}: {}", loc.file, loc.line, loc.column, section.path(), error.message()));
}

}  // namespace fowtsim::driver
