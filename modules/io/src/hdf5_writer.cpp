#include "fowtsim/io/hdf5_writer.hpp"

#include <hdf5.h>

#include <set>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "hdf5_check.hpp"

namespace fowtsim::io {
namespace {

using hdf5::check;
using hdf5::checked;
using hdf5::Handle;

// Root attribute names the writer owns; RunMetadata::extra keys may not reuse them.
const std::set<std::string, std::less<>> kReservedRootAttributes = {
    "version", "deck_path", "deck_hash", "seeds",       "dt_s",
    "dt_coupling_s", "status", "wall_time_s", "end_time_s", "warnings"};

// Replaces attribute `name` of `object` (so finish() can overwrite the "running" status).
Handle create_attribute(hid_t object, const std::string& name, hid_t file_type, hid_t space,
                        const std::string& path) {
  const htri_t exists = H5Aexists(object, name.c_str());
  check(exists, path, "cannot query attribute", name);
  if (exists > 0) check(H5Adelete(object, name.c_str()), path, "cannot replace attribute", name);
  return checked(H5Acreate2(object, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT),
                 H5Aclose, path, "cannot create attribute", name);
}

// Variable-length UTF-8 string: h5py reads it as str (fixed-length strings come back as bytes).
void write_string_attribute(hid_t object, const std::string& name, const std::string& value,
                            const std::string& path) {
  const Handle type = checked(H5Tcopy(H5T_C_S1), H5Tclose, path, "cannot copy string type", name);
  check(H5Tset_size(type.get(), H5T_VARIABLE), path, "cannot size string type", name);
  check(H5Tset_cset(type.get(), H5T_CSET_UTF8), path, "cannot set UTF-8 string type", name);
  const Handle space = checked(H5Screate(H5S_SCALAR), H5Sclose, path, "cannot create dataspace", name);
  const Handle attribute = create_attribute(object, name, type.get(), space.get(), path);
  const char* text = value.c_str();
  check(H5Awrite(attribute.get(), type.get(), &text), path, "cannot write attribute", name);
}

void write_double_attribute(hid_t object, const std::string& name, double value,
                            const std::string& path) {
  const Handle space = checked(H5Screate(H5S_SCALAR), H5Sclose, path, "cannot create dataspace", name);
  const Handle attribute = create_attribute(object, name, H5T_IEEE_F64LE, space.get(), path);
  check(H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, &value), path, "cannot write attribute", name);
}

void write_uint64_array_attribute(hid_t object, const std::string& name,
                                  const std::vector<std::uint64_t>& values, const std::string& path) {
  const hsize_t size = values.size();
  const Handle space = checked(H5Screate_simple(1, &size, nullptr), H5Sclose, path,
                               "cannot create dataspace", name);
  const Handle attribute = create_attribute(object, name, H5T_STD_U64LE, space.get(), path);
  if (!values.empty()) {
    check(H5Awrite(attribute.get(), H5T_NATIVE_UINT64, values.data()), path,
          "cannot write attribute", name);
  }
}

}  // namespace

struct Hdf5Writer::Impl {
  enum class Phase { created, open, finished };

  std::filesystem::path path;
  std::string path_text;                  // path as text, for error messages
  FlushPolicy policy;
  Phase phase = Phase::created;
  Handle file;                            // declared before the datasets: destroyed after them
  std::vector<Handle> datasets;           // Time, then the declared channels
  std::vector<std::string> dataset_names;
  std::vector<double> buffer;             // column-major: buffer[c * rows_per_block + row]
  std::size_t buffered_rows = 0;          // rows in `buffer` not yet in the file
  std::size_t written_rows = 0;           // rows already in the file's datasets

  Impl(std::filesystem::path p, std::size_t rows_per_chunk)
      : path(std::move(p)), path_text(path.string()), policy(rows_per_chunk) {}

  std::size_t block() const { return policy.rows_per_block(); }

  [[noreturn]] void misuse(const std::string& message) const {
    throw Error(ErrorContext{"io.hdf5", std::nullopt, path_text, ""}, message);
  }

  void create_dataset(const ChannelInfo& info) {
    const hsize_t zero = 0;
    const hsize_t unlimited = H5S_UNLIMITED;
    const hsize_t chunk = block();
    const Handle space = checked(H5Screate_simple(1, &zero, &unlimited), H5Sclose, path_text,
                                 "cannot create dataspace", info.name);
    const Handle dcpl = checked(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, path_text,
                                "cannot create property list", info.name);
    check(H5Pset_chunk(dcpl.get(), 1, &chunk), path_text, "cannot set chunk size", info.name);
    // Every element is written before it is read; skipping the fill saves a pass over each chunk.
    check(H5Pset_fill_time(dcpl.get(), H5D_FILL_TIME_NEVER), path_text, "cannot set fill time",
          info.name);
    // No chunk cache: H5Dwrite puts the rows on the disk itself and reports a failed write (a full
    // disk) for its own dataset, and a retry writes them again. Through the cache a chunk whose
    // write failed inside H5Fflush was dropped (seen on a full tmpfs: one channel's block read 0).
    const Handle dapl = checked(H5Pcreate(H5P_DATASET_ACCESS), H5Pclose, path_text,
                                "cannot create property list", info.name);
    check(H5Pset_chunk_cache(dapl.get(), 0, 0, H5D_CHUNK_CACHE_W0_DEFAULT), path_text, "cannot set chunk cache",
          info.name);
    Handle dataset = checked(H5Dcreate2(file.get(), info.name.c_str(), H5T_IEEE_F64LE, space.get(),
                                        H5P_DEFAULT, dcpl.get(), dapl.get()),
                             H5Dclose, path_text, "cannot create dataset", info.name);
    write_string_attribute(dataset.get(), "unit", info.unit, path_text);
    write_string_attribute(dataset.get(), "description", info.description, path_text);
    write_string_attribute(dataset.get(), "module", info.module, path_text);
    datasets.push_back(std::move(dataset));
    dataset_names.push_back(info.name);
  }

  // Writes the buffered rows as one hyperslab per dataset, then flushes the file to disk. The rows
  // leave the buffer only once the flush succeeded: after a failed one (a full disk) HDF5 may hold
  // some of the block's chunks only half written, so a retry writes the whole block again.
  void write_buffered_and_flush() {
    if (buffered_rows > 0) {
      const hsize_t start = written_rows;
      const hsize_t count = buffered_rows;
      const hsize_t new_size = start + count;
      const Handle memory_space = checked(H5Screate_simple(1, &count, nullptr), H5Sclose, path_text,
                                          "cannot create dataspace");
      for (std::size_t c = 0; c < datasets.size(); ++c) {
        const hid_t dataset = datasets[c].get();
        const std::string& name = dataset_names[c];
        check(H5Dset_extent(dataset, &new_size), path_text, "cannot extend dataset", name);
        const Handle file_space = checked(H5Dget_space(dataset), H5Sclose, path_text,
                                          "cannot get dataspace", name);
        check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, &start, nullptr, &count, nullptr),
              path_text, "cannot select rows", name);
        check(H5Dwrite(dataset, H5T_NATIVE_DOUBLE, memory_space.get(), file_space.get(), H5P_DEFAULT,
                       buffer.data() + c * block()),
              path_text, "cannot write rows", name);
      }
    }
    check(H5Fflush(file.get(), H5F_SCOPE_LOCAL), path_text, "cannot flush file");
    written_rows += buffered_rows;
    buffered_rows = 0;
    policy.flushed();
  }
};

Hdf5Writer::Hdf5Writer(std::filesystem::path path, std::size_t rows_per_chunk)
    : impl_(std::make_unique<Impl>(std::move(path), rows_per_chunk)) {}

Hdf5Writer::~Hdf5Writer() {
  if (impl_->phase != Impl::Phase::open) return;
  // Reached without finish(): the run died (exception) or the caller forgot. Keep every appended
  // row and say so in the status; a destructor must not throw, so failures are swallowed here.
  try {
    impl_->write_buffered_and_flush();  // rows first: they matter more than the status
  } catch (...) {
  }
  try {
    write_string_attribute(impl_->file.get(), "status",
                           "incomplete: output closed before the run finished", impl_->path_text);
    H5Fflush(impl_->file.get(), H5F_SCOPE_LOCAL);
  } catch (...) {
  }
  impl_->datasets.clear();
  impl_->file.reset();
}

void Hdf5Writer::begin(const std::vector<ChannelInfo>& channels, const RunMetadata& metadata) {
  Impl& w = *impl_;
  if (w.phase != Impl::Phase::created) w.misuse("begin() called twice");
  std::set<std::string, std::less<>> seen = {"Time"};
  for (const ChannelInfo& channel : channels) {
    if (channel.name.empty() || channel.name == "." || channel.name.find('/') != std::string::npos) {
      w.misuse(fmt::format("channel name '{}' cannot be an HDF5 dataset name", channel.name));
    }
    if (!seen.insert(channel.name).second) {
      w.misuse(fmt::format("channel '{}' declared twice (or named like the time channel)",
                           channel.name));
    }
  }
  for (const auto& [key, value] : metadata.extra) {
    if (kReservedRootAttributes.contains(key)) {
      w.misuse(fmt::format("metadata key '{}' is reserved for the writer", key));
    }
  }

  hdf5::silence_error_printing();
  const Handle fcpl = checked(H5Pcreate(H5P_FILE_CREATE), H5Pclose, w.path_text,
                              "cannot create property list");
  // Readers list channels in creation order, so the file must track (and index) it.
  check(H5Pset_link_creation_order(fcpl.get(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
        w.path_text, "cannot track link creation order");
  w.file = checked(H5Fcreate(w.path_text.c_str(), H5F_ACC_TRUNC, fcpl.get(), H5P_DEFAULT), H5Fclose,
                   w.path_text, "cannot create file");
  // Until begin() returns, a failure leaves a half-made file that is closed right away.
  w.phase = Impl::Phase::open;

  const hid_t root = w.file.get();
  write_string_attribute(root, "version", metadata.version, w.path_text);
  write_string_attribute(root, "deck_path", metadata.deck_path, w.path_text);
  write_string_attribute(root, "deck_hash", metadata.deck_hash, w.path_text);
  write_uint64_array_attribute(root, "seeds", metadata.seeds, w.path_text);
  write_double_attribute(root, "dt_s", metadata.dt_s, w.path_text);
  write_double_attribute(root, "dt_coupling_s", metadata.dt_coupling_s, w.path_text);
  for (const auto& [key, value] : metadata.extra) write_string_attribute(root, key, value, w.path_text);
  write_string_attribute(root, "status", "running", w.path_text);

  w.datasets.reserve(channels.size() + 1);
  w.create_dataset(ChannelInfo{"Time", "s", "simulation time", "driver"});
  for (const ChannelInfo& channel : channels) w.create_dataset(channel);
  w.buffer.assign(w.datasets.size() * w.block(), 0.0);
  w.write_buffered_and_flush();
}

void Hdf5Writer::append(double time_s, std::span<const double> values) {
  Impl& w = *impl_;
  if (w.phase != Impl::Phase::open) w.misuse("append() before begin() or after finish()");
  if (values.size() + 1 != w.datasets.size()) {
    w.misuse(fmt::format("append() got {} values for {} declared channels", values.size(),
                         w.datasets.size() - 1));
  }
  const std::size_t block = w.block();
  if (w.buffered_rows == block) w.write_buffered_and_flush();  // a failed flush left a full block
  double* row = w.buffer.data() + w.buffered_rows;
  row[0] = time_s;
  for (std::size_t c = 0; c < values.size(); ++c) row[(c + 1) * block] = values[c];
  ++w.buffered_rows;
  if (w.policy.due(w.buffered_rows)) w.write_buffered_and_flush();
}

void Hdf5Writer::flush() {
  Impl& w = *impl_;
  if (w.phase == Impl::Phase::open) w.write_buffered_and_flush();
}

void Hdf5Writer::finish(const RunEnd& end) {
  Impl& w = *impl_;
  if (w.phase != Impl::Phase::open) w.misuse("finish() before begin() or called twice");
  const hid_t root = w.file.get();
  write_double_attribute(root, "wall_time_s", end.wall_time_s, w.path_text);
  write_string_attribute(root, "status", end.status, w.path_text);
  write_double_attribute(root, "end_time_s", end.end_time_s, w.path_text);
  std::string warnings;
  for (const std::string& line : end.warnings) warnings += (warnings.empty() ? "" : "\n") + line;
  write_string_attribute(root, "warnings", warnings, w.path_text);
  w.write_buffered_and_flush();
  w.phase = Impl::Phase::finished;
  w.datasets.clear();
  if (!w.file.reset()) hdf5::fail(w.path_text, "cannot close file");
}

const std::filesystem::path& Hdf5Writer::path() const { return impl_->path; }

std::size_t Hdf5Writer::rows_appended() const {
  return impl_->written_rows + impl_->buffered_rows;
}

}  // namespace fowtsim::io
