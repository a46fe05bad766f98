#include "sweep/folder_lock.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <optional>
#include <thread>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::driver::sweep {

namespace fs = std::filesystem;

namespace {

struct Holder {
  long pid = 0;      // 0: the holder has not written its text yet
  std::string host;
  std::string text;  // as written, for messages
};

std::string host_name() {
  char name[256] = {};
  gethostname(name, sizeof name - 1);
  return name;
}

std::string field(const std::string& text, const std::string& key) {
  const std::size_t at = text.find(key + "=");
  if (at == std::string::npos) return "";
  const std::size_t start = at + key.size() + 1;
  return text.substr(start, text.find_first_of(" \n", start) - start);
}

Holder read_holder(int fd) {
  Holder h;
  char buffer[1024];
  const ssize_t n = pread(fd, buffer, sizeof buffer, 0);
  if (n <= 0) return h;
  h.text.assign(buffer, static_cast<std::size_t>(n));
  while (!h.text.empty() && h.text.back() == '\n') h.text.pop_back();
  h.pid = std::strtol(field(h.text, "pid").c_str(), nullptr, 10);
  h.host = field(h.text, "host");
  return h;
}

// A holder on another host, or one not yet named, counts as alive: nothing here can tell otherwise.
bool holder_alive(const Holder& h) {
  if (h.pid <= 0 || h.host != host_name()) return true;
  return kill(static_cast<pid_t>(h.pid), 0) == 0 || errno == EPERM;
}

std::string now_text() {
  const std::time_t t = std::time(nullptr);
  std::tm local{};
  localtime_r(&t, &local);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &local);
  return text;
}

[[noreturn]] void fail(int& fd, const std::string& message, const std::string& hint) {
  close(fd);
  fd = -1;
  throw InputError({"sweep", std::nullopt, "output_dir", hint}, message);
}

}  // namespace

SweepFolderLock::SweepFolderLock(const fs::path& folder, const std::string& command, std::FILE* out,
                                 std::chrono::milliseconds orphan_wait) {
  fs::create_directories(folder);
  const fs::path path = file(folder);
  // Opened without O_TRUNC: the holder's text is read before anything is written.
  fd_ = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw InputError({"sweep", std::nullopt, "output_dir", "a writable folder"}, "cannot open " + path.string() + ": " + std::strerror(errno));
  if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    if (errno != EWOULDBLOCK) fail(fd_, "cannot lock " + path.string() + ": " + std::strerror(errno), "a local folder that supports flock");
    const Holder holder = read_holder(fd_);
    if (holder_alive(holder))
      fail(fd_,
           fmt::format("the output folder {} is in use by another sweep ({}); nothing was changed",
                       folder.string(), holder.pid > 0 ? holder.text : "it is starting"),
           "wait for it to end, or give this sweep another --output-dir");
    // The holder has died; the cases it started still hold the lock while they close their outputs
    // (they got SIGTERM when it died). Writing over those outputs now would lose them: wait.
    fmt::print(out, "  waiting          for the cases of the ended sweep (PID {}) to close their outputs\n", holder.pid);
    std::fflush(out);
    const auto deadline = std::chrono::steady_clock::now() + orphan_wait;
    while (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      if (std::chrono::steady_clock::now() >= deadline)
        fail(fd_,
             fmt::format("the output folder {} is still locked by cases of the sweep PID {}, which has ended ({}); nothing "
                         "was changed",
                         folder.string(), holder.pid, holder.text),
             fmt::format("stop those cases (`fuser -v {}` lists them), then rerun", path.string()));
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }
  const std::string text = fmt::format("pid={} host={} started={} command={}\n", getpid(), host_name(), now_text(), command);
  if (ftruncate(fd_, 0) != 0 || pwrite(fd_, text.data(), text.size(), 0) != static_cast<ssize_t>(text.size()))
    fail(fd_, "cannot write " + path.string() + ": " + std::strerror(errno), "a writable folder");
}

SweepFolderLock::~SweepFolderLock() {
  if (fd_ >= 0) close(fd_);
}

}  // namespace fowtsim::driver::sweep
