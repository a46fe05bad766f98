#include "run/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {
namespace {

std::filesystem::path lock_path(const std::filesystem::path& base) { return base.string() + ".lock"; }

// What the holder wrote into the lock file: "PID <pid> on <host> since <UTC time>".
std::string holder_of(int fd) {
  char text[256] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  std::string holder = n > 0 ? std::string(text, static_cast<std::size_t>(n)) : std::string("an unknown process");
  while (!holder.empty() && (holder.back() == '\n' || holder.back() == '\r')) holder.pop_back();
  return holder;
}

std::string this_holder() {
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char when[32] = {};
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S UTC", &utc);
  return fmt::format("PID {} on {} since {}\n", ::getpid(), host, when);
}

// Whether `fd` still is the file at `path`: a holder that finished unlinks its lock file, and a
// process that opened the old file before that must not believe it holds the name's lock.
bool still_at(int fd, const std::filesystem::path& path) {
  struct stat open_file {}, named {};
  return ::fstat(fd, &open_file) == 0 && ::stat(path.c_str(), &named) == 0 && open_file.st_ino == named.st_ino &&
         open_file.st_dev == named.st_dev;
}

}  // namespace

OutputLock::OutputLock(const std::filesystem::path& base) : path_(lock_path(base)) {
  if (base.has_parent_path()) std::filesystem::create_directories(base.parent_path());
  for (;;) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
      throw InputError({"run", std::nullopt, "-o", "a folder this run can write to"},
                       fmt::format("cannot create {}: {}", path_.string(), std::strerror(errno)));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const std::string holder = holder_of(fd_);
      ::close(fd_);
      fd_ = -1;
      throw InputError({"run", std::nullopt, "-o", "another output name, or wait for that run to end"},
                       fmt::format("the output {} is being written by another run ({}); it holds {}",
                                   base.string(), holder, path_.string()));
    }
    if (still_at(fd_, path_)) break;
    ::close(fd_);  // the previous holder removed the file between our open and our lock: again
  }
  const std::string holder = this_holder();
  // A full disk may refuse the note; the lock holds without it (only a second run's message suffers).
  if (::ftruncate(fd_, 0) == 0) (void)!::pwrite(fd_, holder.data(), holder.size(), 0);
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());  // before the unlock: a waiting opener then finds the name gone (still_at)
  ::close(fd_);
}

bool OutputLock::held_by_another_run(const std::filesystem::path& base) {
  const int fd = ::open(lock_path(base).c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool held = ::flock(fd, LOCK_SH | LOCK_NB) != 0;
  ::close(fd);
  return held;
}

}  // namespace fowtsim::driver
