#pragma once
// Runs cases as separate `fowtsim run` processes, N at a time, on this machine. A process per
// case (not a thread) keeps each run's signals, exit code and memory its own: one failing or
// crashing case cannot take the others down, and a case runs exactly as it would alone.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace fowtsim::driver::sweep {

struct CaseCommand {
  std::string name;                  // case name
  std::vector<std::string> arguments;  // argv after the executable, e.g. {"run", deck, "-o", out}
  std::filesystem::path log;         // stdout and stderr of the process
  double simulated_s = 0.0;          // simulated time the case asks for (ETA and throughput) [s]
};

struct PoolProgress {
  std::size_t done = 0;      // ended with exit code 0
  std::size_t failed = 0;    // ended otherwise
  std::size_t running = 0;   // processes alive
  std::size_t queued = 0;    // not started
  double elapsed_s = 0.0;    // wall time since the pool started [s]
  double eta_s = -1.0;       // estimate of the wall time left [s]; < 0 before a case has ended
  std::string last_case;     // the case that just ended ("" for a periodic update)
  int last_exit_code = 0;    // its exit code
};

struct CaseExit {
  std::string name;
  int exit_code = 0;     // as a shell reports it: 128 + signal for a process killed by a signal
  double wall_s = 0.0;   // wall time of the process [s]
  double cpu_s = 0.0;    // CPU time it used, user + system [s]: its cost whatever else loads the machine
};

struct PoolReport {
  std::vector<CaseExit> ended;  // in the order they ended
  double wall_s = 0.0;          // wall time of the whole pool [s]
  int interrupted_by = 0;       // SIGINT/SIGTERM that stopped the pool, or 0
};

// Runs `commands` with `executable`, at most `jobs` at a time, in their own process group (so that
// a terminal's Ctrl-C reaches only this process, which forwards it once). `on_case_end(exit)` is
// called as each case ends (to record its exit code), `progress` at each end and every ~0.5 s.
// A SIGINT/SIGTERM (run/interrupt.hpp) stops new starts and is forwarded to the running cases,
// which close their outputs as interrupted; the pool waits for them and reports the signal.
// Cases die with the pool: however it ends (even SIGKILL), each running case gets SIGTERM (the
// parent-death signal) and closes its output as interrupted. `kept_descriptor` (≥ 0) stays open
// in every case (the folder lock, folder_lock.hpp: locked until the last case has exited).
PoolReport run_pool(const std::filesystem::path& executable, const std::vector<CaseCommand>& commands, int jobs,
                    const std::function<void(const CaseExit&)>& on_case_end,
                    const std::function<void(const PoolProgress&)>& progress, int kept_descriptor = -1);

// This process's own executable (/proc/self/exe), what a sweep runs its cases with.
std::filesystem::path own_executable();

}  // namespace fowtsim::driver::sweep
