#pragma once
// Private to the io writers: pwrite of a whole byte range, as the text and .outb writers need it
// (a row or a header field is on the disk whole, or the write failed).
#include <unistd.h>

#include <cerrno>
#include <cstddef>

namespace fowtsim::io::detail {

// Writes every byte of [data, data + size) at `offset`, retrying after EINTR and short writes.
// Returns 0, or the errno of the failure (ENOSPC when the system wrote nothing without one).
inline int write_all_at(int fd, const char* data, std::size_t size, off_t offset) {
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::pwrite(fd, data + done, size - done, offset + static_cast<off_t>(done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : ENOSPC;
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

}  // namespace fowtsim::io::detail
