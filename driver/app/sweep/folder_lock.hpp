#pragma once
// One sweep at a time per output folder. Two pools on one folder run the same cases into the same
// temporary outputs and logs, and lose finished results; so a sweep that writes into its folder
// (a local pool, --slurm, --collect) first takes an exclusive flock(2) on OUTPUT_DIR/.sweep.lock,
// whose text names the holder (PID, host, start time, command line). The kernel releases a flock
// when the last descriptor of that open file closes, so a killed sweep never leaves a stale lock:
// the text then only tells who held it last.
//
// The local pool's cases inherit the descriptor (run_pool's `kept_descriptor`), so the folder
// stays locked until the last case of a pool has exited. A pool killed outright (SIGKILL) takes
// its cases down with it (they get SIGTERM, local_pool.hpp) and they close their outputs as
// interrupted; a rerun started meanwhile waits for them rather than writing over those outputs.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

namespace fowtsim::driver::sweep {

class SweepFolderLock {
 public:
  // Takes the lock (creating the folder and the lock file if needed) and writes the holder's text.
  // If a live sweep holds it, throws InputError naming that sweep's PID, host and start, having
  // changed no file. If its holder has died and only the holder's cases still hold it, waits up to
  // `orphan_wait` for them to end (saying so on `out`), then throws naming them if they have not.
  SweepFolderLock(const std::filesystem::path& folder, const std::string& command, std::FILE* out,
                  std::chrono::milliseconds orphan_wait = std::chrono::seconds(30));
  ~SweepFolderLock();
  SweepFolderLock(const SweepFolderLock&) = delete;
  SweepFolderLock& operator=(const SweepFolderLock&) = delete;

  int descriptor() const { return fd_; }  // for children that keep the folder locked while they run
  static std::filesystem::path file(const std::filesystem::path& folder) { return folder / ".sweep.lock"; }

 private:
  int fd_ = -1;
};

}  // namespace fowtsim::driver::sweep
