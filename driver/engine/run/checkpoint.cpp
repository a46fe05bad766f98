#include "run/checkpoint.hpp"

#include <algorithm>
#include <cstring>
#include <iterator>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/deck.hpp"
#include "run/durable_file.hpp"

namespace fowtsim::driver {
namespace {

constexpr std::size_t kPreamble = kCheckpointMagic.size() + 2 * sizeof(std::uint64_t);  // magic, length, checksum

[[noreturn]] void damaged(const std::filesystem::path& file, const std::string& why) {
  throw InputError({"checkpoint", std::nullopt, "--restart", "an undamaged checkpoint: restart from an earlier one"},
                   fmt::format("{}: the checkpoint is damaged: {}", file.string(), why));
}

}  // namespace

void CheckpointReader::mismatch(const std::string& what) const {
  throw InputError({"checkpoint", std::nullopt, "--restart", "a checkpoint written by this deck and build"},
                   fmt::format("{}: {} differs from the scene's: the checkpoint belongs to another deck or build",
                               file_.string(), what));
}

void CheckpointReader::read(char* p, std::size_t n) {
  is_.read(p, static_cast<std::streamsize>(n));
  if (!is_) mismatch("the state's length");
}

std::array<char, 40> hash_field(const std::string& deck_hash) {
  std::array<char, 40> field{};
  std::memcpy(field.data(), deck_hash.data(), std::min(deck_hash.size(), field.size()));
  return field;
}

void write_checkpoint_file(const std::filesystem::path& file, const std::string& payload) {
  std::string bytes(kCheckpointMagic);
  const std::uint64_t length = payload.size(), checksum = io::fnv1a_64(payload);
  bytes.append(reinterpret_cast<const char*>(&length), sizeof length);
  bytes.append(reinterpret_cast<const char*>(&checksum), sizeof checksum);
  bytes += payload;
  write_file_atomically(file, bytes);
}

LoadedCheckpoint read_checkpoint(const std::filesystem::path& file, const std::string& deck_hash, double dt_s) {
  std::ifstream is(file, std::ios::binary);
  if (!is || std::filesystem::is_directory(file))
    throw InputError({"checkpoint", std::nullopt, "--restart", "a readable checkpoint file"},
                     fmt::format("{}: cannot open the checkpoint", file.string()));
  const std::string bytes(std::istreambuf_iterator<char>(is), {});
  if (bytes.compare(0, kCheckpointMagic.size(), kCheckpointMagic) != 0)
    throw InputError({"checkpoint", std::nullopt, "--restart", "a fowtsim checkpoint (.chk)"},
                     fmt::format("{}: not a fowtsim checkpoint of this version (format {})", file.string(), kCheckpointMagic));
  if (bytes.size() < kPreamble) damaged(file, fmt::format("{} bytes, shorter than its own preamble", bytes.size()));
  std::uint64_t length = 0, checksum = 0;
  std::memcpy(&length, bytes.data() + kCheckpointMagic.size(), sizeof length);
  std::memcpy(&checksum, bytes.data() + kCheckpointMagic.size() + sizeof length, sizeof checksum);
  const std::string_view payload = std::string_view(bytes).substr(kPreamble);
  if (payload.size() != length)
    damaged(file, fmt::format("{} bytes of state where it declares {} (cut short, e.g. by a full disk)", payload.size(), length));
  if (io::fnv1a_64(payload) != checksum) damaged(file, "its checksum does not match its content");

  LoadedCheckpoint loaded{{}, {}, std::istringstream(std::string(payload))};
  CheckpointReader r(loaded.state, file);
  r.get(loaded.header);
  std::vector<char> base;
  r.get(base);
  loaded.output_base = std::string(base.begin(), base.end());
  if (loaded.header.deck_hash != hash_field(deck_hash)) r.mismatch("the deck hash (the deck or one of its includes changed)");
  if (loaded.header.dt_s != dt_s) r.mismatch(fmt::format("the time step ({} s)", loaded.header.dt_s));
  return loaded;
}

}  // namespace fowtsim::driver
