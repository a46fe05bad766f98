#include "run/durable_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {
namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what, int error_number) {
  throw Error({"output", std::nullopt, file.string(), "check free disk space and the folder's permissions"},
              fmt::format("{} {}: {}", what, file.string(), std::strerror(error_number)));
}

// Closes the descriptor on every path out of the function.
struct Descriptor {
  int fd = -1;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

void write_file_atomically(const std::filesystem::path& file, std::string_view bytes) {
  const std::filesystem::path tmp = file.string() + ".tmp";
  auto give_up = [&](const std::string& what, int error_number) {
    ::unlink(tmp.c_str());
    fail(file, what, error_number);
  };
  {
    Descriptor d{::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644)};
    if (d.fd < 0) fail(tmp, "cannot create", errno);
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::write(d.fd, bytes.data() + done, bytes.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) give_up(fmt::format("cannot write ({} of {} bytes written)", done, bytes.size()), n < 0 ? errno : ENOSPC);
      done += static_cast<std::size_t>(n);
    }
    if (::fsync(d.fd) != 0) give_up("cannot sync", errno);
    const int fd = d.fd;
    d.fd = -1;
    if (::close(fd) != 0) give_up("cannot close", errno);
  }
  if (::rename(tmp.c_str(), file.c_str()) != 0) give_up("cannot rename the temporary to", errno);
  // The rename itself is durable only once the folder is synced.
  const std::filesystem::path folder = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  Descriptor dir{::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)};
  if (dir.fd >= 0) ::fsync(dir.fd);  // best effort: some file systems refuse fsync on a folder
}

void sync_file(const std::filesystem::path& file) {
  Descriptor d{::open(file.c_str(), O_RDONLY | O_CLOEXEC)};
  if (d.fd < 0) fail(file, "cannot open", errno);
  if (::fsync(d.fd) != 0) fail(file, "cannot sync", errno);
}

}  // namespace fowtsim::driver
