#pragma once
// Checkpoints of a fixed-step scene (issue 16): the whole changing state of a scene in one binary
// file, so that `fowtsim run DECK --restart FILE` continues bit-identically to an uninterrupted
// run. Values are written as their bytes (doubles bit for bit); a header ties the file to the
// deck (hash), the step and the time step, and the reader refuses anything else. Both archives
// have io(x): a struct with a field list (core/fields.hpp: `fields(archive, value)`, found by
// argument-dependent lookup) is written through it, anything else as its bytes; the one list serves
// saving and loading alike, so the two can never disagree on order, and `state_bytes` compares.
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <variant>
#include <type_traits>
#include <vector>

#include <Eigen/Geometry>

#include "fowtsim/core/types.hpp"

namespace fowtsim::driver {

template <class Archive, class T>
concept HasFieldList = requires(Archive& a, T& v) { fields(a, v); };

class CheckpointWriter {
 public:
  explicit CheckpointWriter(std::ostream& os) : os_(os) {}
  template <class T>
    requires(std::is_trivially_copyable_v<T> && !HasFieldList<CheckpointWriter, T>)
  void put(const T& v) {
    os_.write(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  template <class S, int R, int C, int O, int MR, int MC>
  void put(const Eigen::Matrix<S, R, C, O, MR, MC>& m) {
    if constexpr (R == Eigen::Dynamic || C == Eigen::Dynamic) {
      put(static_cast<std::int64_t>(m.rows()));
      put(static_cast<std::int64_t>(m.cols()));
    }
    os_.write(reinterpret_cast<const char*>(m.data()), static_cast<std::streamsize>(sizeof(S) * m.size()));
  }
  void put(const Eigen::Quaterniond& q) { put(Eigen::Vector4d(q.coeffs())); }
  template <class T>
  void put(const std::vector<T>& v) {
    put(static_cast<std::uint64_t>(v.size()));
    for (const T& x : v) put(x);
  }
  template <class T, std::size_t N>
  void put(const std::array<T, N>& a) {
    for (const T& x : a) put(x);
  }
  template <class T>
  void put(const std::optional<T>& o) {  // present or not as the deck says: the same on both sides
    if (o) put(*o);
  }
  template <class... T>
  void put(const std::variant<T...>& v) {
    put(static_cast<std::uint64_t>(v.index()));
    std::visit([&](const auto& x) { put(x); }, v);
  }
  template <class T>
    requires HasFieldList<CheckpointWriter, T>
  void put(const T& v) {
    fields(*this, const_cast<T&>(v));  // a field list names fields for reading and writing alike
  }
  template <class... T>
  void io(const T&... v) {
    (put(v), ...);
  }
  template <class... T>
  void scratch(const T&...) {}  // workspace: overwritten before it is read

 private:
  std::ostream& os_;
};

class CheckpointReader {
 public:
  CheckpointReader(std::istream& is, std::filesystem::path file) : is_(is), file_(std::move(file)) {}
  template <class T>
    requires(std::is_trivially_copyable_v<T> && !HasFieldList<CheckpointReader, T>)
  void get(T& v) {
    read(reinterpret_cast<char*>(&v), sizeof(T));
  }
  // A dynamic matrix must already have the size the writer had.
  template <class S, int R, int C, int O, int MR, int MC>
  void get(Eigen::Matrix<S, R, C, O, MR, MC>& m) {
    if constexpr (R == Eigen::Dynamic || C == Eigen::Dynamic) {
      std::int64_t rows = 0, cols = 0;
      get(rows);
      get(cols);
      if (rows != m.rows() || cols != m.cols()) mismatch("a matrix's size");
    }
    read(reinterpret_cast<char*>(m.data()), sizeof(S) * static_cast<std::size_t>(m.size()));
  }
  void get(Eigen::Quaterniond& q) {
    Eigen::Vector4d c;
    get(c);
    q.coeffs() = c;
  }
  // A vector of the size the writer had; `expected` (if ≥ 0) must match it.
  template <class T>
  void get(std::vector<T>& v, long expected = -1) {
    std::uint64_t n = 0;
    get(n);
    if (expected >= 0 && n != static_cast<std::uint64_t>(expected)) mismatch("a vector's size");
    v.resize(n);
    for (T& x : v) get(x);
  }
  template <class T, std::size_t N>
  void get(std::array<T, N>& a) {
    for (T& x : a) get(x);
  }
  template <class T>
  void get(std::optional<T>& o) {
    if (o) get(*o);
  }
  template <class... T>
  void get(std::variant<T...>& v) {
    std::uint64_t index = 0;
    get(index);
    if (index != v.index()) mismatch("a variant's alternative");
    std::visit([&](auto& x) { get(x); }, v);
  }
  template <class T>
    requires HasFieldList<CheckpointReader, T>
  void get(T& v) {
    fields(*this, v);
  }
  template <class... T>
  void io(T&... v) {
    (get(v), ...);
  }
  template <class... T>
  void scratch(T&...) {}
  [[noreturn]] void mismatch(const std::string& what) const;

 private:
  void read(char* p, std::size_t n);
  std::istream& is_;
  std::filesystem::path file_;
};

// The bytes a state's field lists write: two states are the same when these are.
template <class State>
std::string state_bytes(const State& state) {
  std::ostringstream os;
  CheckpointWriter w(os);
  w.io(state);
  return std::move(os).str();
}

struct CheckpointHeader {
  std::array<char, 40> deck_hash{};  // io::ValidatedDeck::hash(), zero-padded
  long step = 0;        // large steps taken
  double dt_s = 0.0;    // the scene's step
};

// File layout (format FOWTSIMCHK5): the 11-byte magic, the payload's length and its FNV-1a 64
// checksum (two uint64), then the payload: the header, the output base of the run that wrote it
// (so a restart continues that output) and the scene's state through its field lists. The format
// number rises whenever a state field changes its layout or meaning, so that an older checkpoint is
// refused rather than continued wrongly (5: the MBBT blades' held root loads no longer include the
// blades' weight, scenes/turbine_blades.hpp).
inline constexpr std::string_view kCheckpointMagic = "FOWTSIMCHK5";

// Writes magic, length, checksum and `payload` to `file` complete or not at all.
void write_checkpoint_file(const std::filesystem::path& file, const std::string& payload);

// Writes the checkpoint complete or not at all (run/durable_file.hpp: temporary, fsync, rename):
// a full disk or a kill while writing leaves the previous checkpoint. Throws fowtsim::Error.
template <class SaveScene>
void write_checkpoint(const std::filesystem::path& file, const CheckpointHeader& header,
                      const std::filesystem::path& output_base, SaveScene&& save) {
  std::ostringstream payload;
  CheckpointWriter w(payload);
  w.put(header);
  const std::string base = output_base.string();
  w.put(std::vector<char>(base.begin(), base.end()));
  save(w);
  write_checkpoint_file(file, std::move(payload).str());
}

// A checkpoint read whole and checked: the reader continues with the scene's state in `state`.
struct LoadedCheckpoint {
  CheckpointHeader header;
  std::filesystem::path output_base;  // the output of the run that wrote it, without extension
  std::istringstream state;
};

// Reads `file` and checks, each with its own InputError naming the file: that it is a checkpoint
// of this format, that it is whole (length and checksum: "damaged", e.g. cut short by a full
// disk), and that it belongs to `deck_hash` with step `dt_s` (another deck or build).
LoadedCheckpoint read_checkpoint(const std::filesystem::path& file, const std::string& deck_hash, double dt_s);
std::array<char, 40> hash_field(const std::string& deck_hash);

}  // namespace fowtsim::driver
