#include "run/checkpoint.hpp"

#include <algorithm>
#include <cstring>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

void CheckpointReader::mismatch(const std::string& what) const {
  throw InputError({"checkpoint", std::nullopt, "--restart", "a checkpoint written by this deck and build"},
                   fmt::format("{}: {} differs from the scene's: the checkpoint belongs to another deck or build",
                               file_.string(), what));
}

void CheckpointReader::read(char* p, std::size_t n) {
  is_.read(p, static_cast<std::streamsize>(n));
  if (!is_) mismatch("the file ends early: its length");
}

std::array<char, 40> hash_field(const std::string& deck_hash) {
  std::array<char, 40> field{};
  std::memcpy(field.data(), deck_hash.data(), std::min(deck_hash.size(), field.size()));
  return field;
}

CheckpointHeader read_checkpoint_header(std::ifstream& is, const std::filesystem::path& file, const std::string& deck_hash,
                                        double dt_s) {
  if (!is)
    throw InputError({"checkpoint", std::nullopt, "--restart", "a readable checkpoint file"},
                     fmt::format("{}: cannot open the checkpoint", file.string()));
  char magic[11] = {};
  is.read(magic, 11);
  if (!is || std::memcmp(magic, "FOWTSIMCHK3", 11) != 0)
    throw InputError({"checkpoint", std::nullopt, "--restart", "a fowtsim checkpoint (.chk)"},
                     fmt::format("{}: not a fowtsim checkpoint of this version (format FOWTSIMCHK3)", file.string()));
  CheckpointReader r(is, file);
  CheckpointHeader h;
  r.get(h);
  if (h.deck_hash != hash_field(deck_hash)) r.mismatch("the deck hash (the deck or one of its includes changed)");
  if (h.dt_s != dt_s) r.mismatch(fmt::format("the time step ({} s)", h.dt_s));
  return h;
}

}  // namespace fowtsim::driver
