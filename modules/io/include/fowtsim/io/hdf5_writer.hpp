#pragma once
// The default output: one HDF5 file per run (DESIGN.md §6).
//
// File layout (h5py: f["RotSpeed"][:], f["RotSpeed"].attrs["unit"], f.attrs["status"]):
//   /Time, /<channel>...   1-D float64 datasets, chunked and extendible, one per channel, in the
//                          order declared (the file tracks link creation order; Time is first)
//     attrs unit, description, module      variable-length UTF-8 strings (Time: "s", module "driver")
//   root attrs version, deck_path, deck_hash (strings), seeds (uint64 array), dt_s, dt_coupling_s
//              (float64), one string attribute per RunMetadata::extra pair, status ("running"
//              until finish), and at finish wall_time_s, end_time_s (float64).
//
// Writing is incremental and crash-safe: rows are buffered in memory (allocated once, at begin)
// and written as a block of `rows_per_chunk` rows, followed by H5Fflush, so the file on disk is
// always a valid HDF5 file holding every complete block. append() touches HDF5 only when a block
// is full, or when ~2 s of wall clock passed since the last flush. The destructor writes what is
// buffered and closes the file without throwing, so a run that dies by exception keeps every
// appended row (its status then says it did not complete).
#include <cstddef>
#include <filesystem>
#include <memory>
#include <span>
#include <vector>

#include "fowtsim/io/output_sink.hpp"

namespace fowtsim::io {

class Hdf5Writer final : public OutputSink {
 public:
  // The file is created (truncated if present) by begin(). rows_per_chunk is both the HDF5 chunk
  // length and the number of rows buffered between block writes.
  explicit Hdf5Writer(std::filesystem::path path, std::size_t rows_per_chunk = 1024);
  ~Hdf5Writer() override;

  void begin(const std::vector<ChannelInfo>& channels, const RunMetadata& metadata) override;
  void append(double time_s, std::span<const double> values) override;
  void flush() override;
  void finish(const RunEnd& end) override;

  const std::filesystem::path& path() const;
  // Rows appended so far (written or still buffered).
  std::size_t rows_appended() const;

 private:
  struct Impl;  // keeps hdf5.h out of this header (hdf5 is a private dependency of fowtsim::io)
  std::unique_ptr<Impl> impl_;
};

}  // namespace fowtsim::io
