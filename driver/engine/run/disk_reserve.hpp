#pragma once
// Disk space held back for the end of a run: a full disk must still let the run write the rows it
// holds in memory, its status and the files' closing records. The reserve is a file of allocated
// blocks next to the outputs (posix_fallocate); when a write fails it is released, and the writers
// retry into the space it leaves.
#include <cstdint>
#include <filesystem>

namespace fowtsim::driver {

class DiskReserve {
 public:
  DiskReserve() = default;
  // Allocates `bytes` in `file`. Throws fowtsim::Error naming the folder and its free space when
  // the disk cannot hold even that much (before any output file is created).
  DiskReserve(std::filesystem::path file, std::uint64_t bytes);
  ~DiskReserve() { release(); }
  DiskReserve(const DiskReserve&) = delete;
  DiskReserve& operator=(const DiskReserve&) = delete;
  DiskReserve(DiskReserve&& other) noexcept : file_(std::move(other.file_)) { other.file_.clear(); }
  DiskReserve& operator=(DiskReserve&& other) noexcept;

  // Frees the space (removes the file); true if there was a reserve to free.
  bool release() noexcept;

 private:
  std::filesystem::path file_;
};

// Bytes an unprivileged process may still write on the file system holding `folder` (statvfs).
std::uint64_t free_bytes(const std::filesystem::path& folder);

}  // namespace fowtsim::driver
