#pragma once
// One run per output name: a run holds an exclusive lock on <base>.lock (flock) for as long as it
// writes <base>.h5/.out/.chk, so a second run on the same name stops before touching any file and
// names the holder. The kernel drops the lock when the holder dies, however it dies (SIGKILL
// included), so a lock file left behind never blocks a later run.
#include <filesystem>
#include <string>

namespace fowtsim::driver {

class OutputLock {
 public:
  // Takes the lock on base + ".lock" (creating the folder and the file). If a live run holds it,
  // throws InputError naming that run's PID, host and start, and the option to change (-o).
  explicit OutputLock(const std::filesystem::path& base);
  // Removes the lock file and releases the lock.
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  const std::filesystem::path& path() const { return path_; }

  // Whether a live run holds the lock of `base` now (a lock this process holds counts too).
  static bool held_by_another_run(const std::filesystem::path& base);

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

}  // namespace fowtsim::driver
