#include "row_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "status_field.hpp"

namespace fowtsim::io::detail {
namespace {

// Writes every byte of [data, data + size) at `offset`, retrying after EINTR and short writes.
// Returns 0, or the errno of the failure (ENOSPC when the system wrote nothing without one).
int write_all_at(int fd, const char* data, std::size_t size, off_t offset) {
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::pwrite(fd, data + done, size - done, offset + static_cast<off_t>(done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : ENOSPC;
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

}  // namespace

RowFile::RowFile(const char* component, std::string path_text)
    : component_(component), path_text_(std::move(path_text)) {}

RowFile::~RowFile() {
  if (fd_ >= 0) ::close(fd_);
}

void RowFile::fail(const std::string& message, const std::string& hint) const {
  throw Error(ErrorContext{component_, std::nullopt, path_text_, hint}, message);
}

void RowFile::create() {
  fd_ = ::open(path_text_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) fail(fmt::format("cannot create the file: {}", std::strerror(errno)), "check that the folder exists and is writable");
}

void RowFile::write_at(const void* data, std::size_t size, off_t offset, std::string_view what) {
  if (const int error = write_all_at(fd_, static_cast<const char*>(data), size, offset)) {
    if (offset >= durable_bytes_) (void)!::ftruncate(fd_, durable_bytes_);
    fail(fmt::format("cannot write {}: {}", what, std::strerror(error)), "check free disk space");
  }
}

void RowFile::append(const void* data, std::size_t size, std::string_view what) {
  write_at(data, size, durable_bytes_, what);
  durable_bytes_ += static_cast<off_t>(size);
}

void RowFile::write_status(const std::string& status) {
  const std::string field = status_field(status);
  write_at(field.data(), field.size(), status_offset_, "the status");
}

void RowFile::close() {
  // Marked closed first: the descriptor is released even when close fails, and the destructor must
  // not close it (or a file opened since under its number) again.
  const int f = fd_;
  fd_ = -1;
  if (::close(f) != 0) fail(fmt::format("cannot close the file: {}", std::strerror(errno)), "check free disk space");
}

}  // namespace fowtsim::io::detail
