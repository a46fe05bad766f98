#include "run/disk_reserve.hpp"

#include <fcntl.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

DiskReserve::DiskReserve(std::filesystem::path file, std::uint64_t bytes) : file_(std::move(file)) {
  const int fd = ::open(file_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const int error = fd < 0 ? errno : ::posix_fallocate(fd, 0, static_cast<off_t>(bytes));
  if (fd >= 0) ::close(fd);
  if (error != 0) {
    const std::filesystem::path folder = file_.has_parent_path() ? file_.parent_path() : ".";
    release();
    throw Error({"output", std::nullopt, folder.string(), "free some space, or write the outputs elsewhere (-o)"},
                fmt::format("cannot hold back {:.1f} MB on the disk of {} for closing the outputs ({:.1f} MB free): {}",
                            static_cast<double>(bytes) / 1e6, folder.string(), static_cast<double>(free_bytes(folder)) / 1e6,
                            std::strerror(error)));
  }
}

DiskReserve& DiskReserve::operator=(DiskReserve&& other) noexcept {
  if (this != &other) {
    release();
    file_ = std::move(other.file_);
    other.file_.clear();
  }
  return *this;
}

bool DiskReserve::release() noexcept {
  if (file_.empty()) return false;
  ::unlink(file_.c_str());
  file_.clear();
  return true;
}

std::uint64_t free_bytes(const std::filesystem::path& folder) {
  struct statvfs s {};
  if (::statvfs(folder.empty() ? "." : folder.c_str(), &s) != 0) return 0;
  return static_cast<std::uint64_t>(s.f_bavail) * s.f_frsize;
}

}  // namespace fowtsim::driver
