#include "sweep/local_pool.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <thread>

#include "fowtsim/core/error.hpp"
#include "run/interrupt.hpp"

namespace fowtsim::driver::sweep {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct RunningCase {
  pid_t pid = 0;
  std::size_t index = 0;
  Clock::time_point start;
};

// Starts one case; returns its pid, or 0 (with the reason in its log) if it could not start.
// fork + exec rather than posix_spawn, for the parent-death signal: a case must not outlive its
// pool (a pool killed outright would leave it running as an orphan, writing the very outputs a
// rerun writes). Everything the child needs is prepared before the fork; the child makes only
// async-signal-safe calls.
pid_t spawn_case(const std::filesystem::path& executable, const CaseCommand& command, int kept_descriptor) {
  std::vector<std::string> words = {executable.string()};
  words.insert(words.end(), command.arguments.begin(), command.arguments.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);

  const auto cannot_start = [&](const char* what, int error) {
    std::ofstream(command.log, std::ios::app) << "fowtsim: cannot start " << executable.string() << ": " << what << ": "
                                              << std::strerror(error) << "\n";
    return pid_t{0};
  };
  const int log = open(command.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log < 0) return cannot_start("its log", errno);
  const int null_input = open("/dev/null", O_RDONLY | O_CLOEXEC);
  int exec_error[2];  // the child reports a failed exec through it; a successful exec closes it
  if (null_input < 0 || pipe2(exec_error, O_CLOEXEC) != 0) {
    const int error = errno;
    close(log);
    if (null_input >= 0) close(null_input);
    return cannot_start("a pipe", error);
  }
  const pid_t pool = getpid();
  const pid_t pid = fork();
  if (pid == 0) {
    // Own process group: a terminal's Ctrl-C reaches the sweep only, which forwards it once (a
    // second SIGINT would kill a run at once instead of letting it close its output).
    setpgid(0, 0);
    // SIGTERM when the pool dies: the run closes its output as interrupted and ends. If the pool
    // died before this call, the signal would never come: stop now.
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != pool) _exit(143);
    // Default dispositions and an empty mask, whatever the sweep inherited (nohup, a shell's `&`).
    struct sigaction default_action {};
    default_action.sa_handler = SIG_DFL;
    sigaction(SIGINT, &default_action, nullptr);
    sigaction(SIGTERM, &default_action, nullptr);
    sigset_t empty;
    sigemptyset(&empty);
    sigprocmask(SIG_SETMASK, &empty, nullptr);
    dup2(null_input, STDIN_FILENO);
    dup2(log, STDOUT_FILENO);
    dup2(log, STDERR_FILENO);
    if (kept_descriptor >= 0) fcntl(kept_descriptor, F_SETFD, 0);  // kept across exec (the folder lock)
    execv(argv[0], argv.data());
    const int error = errno;
    (void)!write(exec_error[1], &error, sizeof error);
    _exit(127);
  }
  const int fork_error = errno;
  close(exec_error[1]);
  close(log);
  close(null_input);
  if (pid < 0) {
    close(exec_error[0]);
    return cannot_start("fork", fork_error);
  }
  int error = 0;
  ssize_t n;
  while ((n = read(exec_error[0], &error, sizeof error)) < 0 && errno == EINTR) {}
  close(exec_error[0]);
  if (n > 0) {
    waitpid(pid, nullptr, 0);
    return cannot_start("exec", error);
  }
  return pid;
}

int exit_code_of(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

}  // namespace

std::filesystem::path own_executable() { return std::filesystem::read_symlink("/proc/self/exe"); }

PoolReport run_pool(const std::filesystem::path& executable, const std::vector<CaseCommand>& commands, int jobs,
                    const std::function<void(const CaseExit&)>& on_case_end,
                    const std::function<void(const PoolProgress&)>& progress, int kept_descriptor) {
  if (jobs < 1) throw std::logic_error("run_pool: jobs < 1");
  const Clock::time_point start = Clock::now();
  PoolReport report;
  std::vector<RunningCase> running;
  std::size_t next = 0, failed = 0;
  double ended_wall_s = 0.0;
  Clock::time_point last_progress = start;

  auto status_now = [&](const std::string& last_case, int last_exit) {
    PoolProgress p;
    p.done = report.ended.size() - failed;
    p.failed = failed;
    p.running = running.size();
    p.queued = report.interrupted_by ? 0 : commands.size() - next;
    p.elapsed_s = seconds_since(start);
    if (!report.ended.empty()) {
      const double mean_wall_s = ended_wall_s / static_cast<double>(report.ended.size());
      p.eta_s = mean_wall_s * static_cast<double>(p.queued + p.running) / std::min<double>(jobs, std::max<std::size_t>(1, p.queued + p.running));
    }
    p.last_case = last_case;
    p.last_exit_code = last_exit;
    return p;
  };
  auto finish = [&](std::size_t index, int exit_code, double wall_s, double cpu_s) {
    CaseExit e{commands[index].name, exit_code, wall_s, cpu_s};
    if (exit_code != 0) ++failed;
    ended_wall_s += wall_s;
    report.ended.push_back(e);
    on_case_end(e);
    progress(status_now(e.name, exit_code));
  };

  while (true) {
    if (!report.interrupted_by && interrupt_signal()) {
      // Stop starting cases; the running ones get the signal once and close their outputs.
      report.interrupted_by = interrupt_signal();
      for (const RunningCase& r : running) kill(r.pid, report.interrupted_by);
    }
    while (!report.interrupted_by && running.size() < static_cast<std::size_t>(jobs) && next < commands.size()) {
      const std::size_t index = next++;
      if (const pid_t pid = spawn_case(executable, commands[index], kept_descriptor); pid > 0)
        running.push_back({pid, index, Clock::now()});
      else
        finish(index, 127, 0.0, 0.0);  // 127: the shell's "command could not be run"
    }
    if (running.empty()) break;

    int status = 0;
    rusage usage{};
    const pid_t pid = wait4(-1, &status, WNOHANG, &usage);
    if (pid > 0) {
      const auto it = std::find_if(running.begin(), running.end(), [&](const RunningCase& r) { return r.pid == pid; });
      if (it == running.end()) continue;  // not one of ours
      const RunningCase ended = *it;
      running.erase(it);
      const double cpu_s = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                           1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
      finish(ended.index, exit_code_of(status), seconds_since(ended.start), cpu_s);
      continue;
    }
    if (pid < 0 && errno != EINTR && errno != ECHILD) throw Error({"sweep", std::nullopt, "", ""}, std::string("wait4: ") + std::strerror(errno));
    if (seconds_since(last_progress) >= 0.5) {
      last_progress = Clock::now();
      progress(status_now("", 0));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  report.wall_s = seconds_since(start);
  return report;
}

}  // namespace fowtsim::driver::sweep
