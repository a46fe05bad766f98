// A real single-node Slurm (issue 14): munged, slurmctld and slurmd started on this machine with a
// minimal slurm.conf in a temporary folder, the small sweep submitted with `fowtsim sweep --slurm`
// as a job array, collected, and its load table checked equal to the local sweep's. Needs root and
// Debian's slurm-wlm and munge (tools/lib/setup.sh installs them); SKIPPED with the reason
// otherwise, or when the daemons do not come up. Run alone: ctest -R 'Slurm' --output-on-failure.
#include <catch2/catch.hpp>

#include <pwd.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <regex>
#include <thread>

#include <fmt/format.h>

#include "sweep_test_spec.hpp"

using namespace fowtsim;
using namespace fowtsim::sweep_test;

namespace {

using namespace std::chrono_literals;

std::string command_output(const std::string& command) {
  std::string output;
  if (FILE* pipe = popen((command + " 2>&1").c_str(), "r")) {
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
    pclose(pipe);
  }
  return output;
}

std::string tail(const std::filesystem::path& file, std::size_t chars = 600) {
  const std::string text = read_text(file);
  return text.size() > chars ? "…" + text.substr(text.size() - chars) : text;
}

// munged, slurmctld and slurmd on localhost, stopped by PID (never by name) when it goes.
class SingleNodeSlurm {
 public:
  SingleNodeSlurm() {
    if (geteuid() != 0) testing::skip("the Slurm test starts slurmd and munged, which needs root");
    for (const char* daemon : {"/usr/sbin/munged", "/usr/sbin/slurmctld", "/usr/sbin/slurmd", "/usr/bin/sbatch"})
      if (!std::filesystem::exists(daemon))
        testing::skip(fmt::format("{} not installed (Debian's slurm-wlm and munge: tools/lib/setup.sh installs them)", daemon));
    const passwd* munge = getpwnam("munge");
    if (munge == nullptr) testing::skip("no munge user (Debian's munge package creates it)");

    // /tmp, not the build tree: the munge socket path must fit a Unix socket name (108 bytes), and
    // the munge user must be able to reach its folder.
    char pattern[] = "/tmp/fowtsim-slurm-XXXXXX";
    if (mkdtemp(pattern) == nullptr) testing::skip("cannot create a temporary folder in /tmp");
    dir_ = pattern;
    std::filesystem::permissions(dir_, std::filesystem::perms::owner_all | std::filesystem::perms::group_read |
                                           std::filesystem::perms::group_exec | std::filesystem::perms::others_read |
                                           std::filesystem::perms::others_exec);
    for (const char* sub : {"munge", "state", "spool"}) std::filesystem::create_directories(dir_ / sub);
    if (chown((dir_ / "munge").c_str(), munge->pw_uid, munge->pw_gid) != 0) skip_and_stop("cannot hand the munge folder to the munge user");

    // A private munge socket, so that a munged already running on the machine is left alone.
    const std::filesystem::path socket = dir_ / "munge/munge.socket";
    start("munged", fmt::format("runuser -u munge -- /usr/sbin/munged --socket={0} --pid-file={1}/munge/munged.pid "
                            "--log-file={1}/munge/munged.log --seed-file={1}/munge/seed > {1}/munged.out 2>&1",
                            socket.string(), dir_.string()));
    if (!wait_for_pid(dir_ / "munge/munged.pid")) skip_and_stop("munged did not start: " + tail(dir_ / "munged.out") + tail(dir_ / "munge/munged.log"));

    // Private ports, from the process id, so that two test runs on one machine do not meet.
    const int port = 20000 + static_cast<int>(getpid() % 5000) * 2;
    const std::string host = command_output("hostname -s");
    hostname_ = host.substr(0, host.find_first_of("\r\n"));
    std::ofstream(dir_ / "slurm.conf") << fmt::format(
        "ClusterName=fowtsimtest\nSlurmctldHost={0}\nSlurmctldPort={2}\nSlurmdPort={3}\nSlurmUser=root\nSlurmdUser=root\n"
        "AuthType=auth/munge\nCredType=cred/munge\nAuthInfo=socket={4}\n"
        "StateSaveLocation={1}/state\nSlurmdSpoolDir={1}/spool\nSlurmctldPidFile={1}/slurmctld.pid\nSlurmdPidFile={1}/slurmd.pid\n"
        "SlurmctldLogFile={1}/slurmctld.log\nSlurmdLogFile={1}/slurmd.log\n"
        "ProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\nSelectType=select/cons_tres\nSelectTypeParameters=CR_Core\n"
        "SchedulerType=sched/backfill\nJobAcctGatherType=jobacct_gather/none\nAccountingStorageType=accounting_storage/none\n"
        "ReturnToService=2\nMpiDefault=none\n"
        "NodeName={0} CPUs=2 State=UNKNOWN\nPartitionName=debug Nodes={0} Default=YES MaxTime=INFINITE State=UP\n",
        hostname_, dir_.string(), port, port + 1, socket.string());
    setenv("SLURM_CONF", (dir_ / "slurm.conf").c_str(), 1);  // for the daemons, sbatch, squeue and sinfo

    start("slurmctld", fmt::format("/usr/sbin/slurmctld > {0}/slurmctld.out 2>&1", dir_.string()));
    if (!wait_for_pid(dir_ / "slurmctld.pid")) skip_and_stop("slurmctld did not start: " + tail(dir_ / "slurmctld.out") + tail(dir_ / "slurmctld.log"));
    start("slurmd", fmt::format("/usr/sbin/slurmd > {0}/slurmd.out 2>&1", dir_.string()));
    if (!wait_for_pid(dir_ / "slurmd.pid")) skip_and_stop("slurmd did not start: " + tail(dir_ / "slurmd.out") + tail(dir_ / "slurmd.log"));
    const auto deadline = std::chrono::steady_clock::now() + 30s;
    while (command_output("sinfo -h -o %T").find("idle") == std::string::npos) {
      if (std::chrono::steady_clock::now() > deadline)
        skip_and_stop("the node did not become idle in 30 s: sinfo says " + command_output("sinfo -h") + "; " + tail(dir_ / "slurmd.log"));
      std::this_thread::sleep_for(200ms);
    }
  }
  SingleNodeSlurm(const SingleNodeSlurm&) = delete;
  SingleNodeSlurm& operator=(const SingleNodeSlurm&) = delete;
  ~SingleNodeSlurm() {
    stop();
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }

  // Waits until the job has left the queue; false after `timeout`.
  bool wait_for_job(const std::string& job_id, std::chrono::seconds timeout) const {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < deadline) {
      if (command_output("squeue -h -j " + job_id + " -o %i").find_first_not_of(" \r\n") == std::string::npos) return true;
      std::this_thread::sleep_for(500ms);
    }
    return false;
  }
  std::string logs() const { return tail(dir_ / "slurmctld.log") + "\n" + tail(dir_ / "slurmd.log"); }

 private:
  // Runs a daemon's start command (it forks into the background and returns).
  void start(const char* daemon, const std::string& command) {
    if (const int status = std::system(command.c_str()); status != 0)
      skip_and_stop(fmt::format("{} did not start (status {}): {}", daemon, status, command_output("cat " + (dir_ / "*.out").string())));
  }
  // Daemons write their pid file once they run in the background; the file names the pid to stop.
  bool wait_for_pid(const std::filesystem::path& pid_file) {
    const auto deadline = std::chrono::steady_clock::now() + 15s;
    while (std::chrono::steady_clock::now() < deadline) {
      std::ifstream in(pid_file);
      pid_t pid = 0;
      if (in >> pid && pid > 0 && kill(pid, 0) == 0) {
        pids_.push_back(pid);
        return true;
      }
      std::this_thread::sleep_for(100ms);
    }
    return false;
  }
  [[noreturn]] void skip_and_stop(const std::string& why) {
    stop();  // testing::skip ends the process without destructors
    testing::skip(why);
  }
  void stop() {
    // slurmd first, then the controller, then munge: each by the PID it wrote.
    for (auto it = pids_.rbegin(); it != pids_.rend(); ++it) {
      kill(*it, SIGTERM);
      for (int i = 0; i < 100 && kill(*it, 0) == 0; ++i) std::this_thread::sleep_for(100ms);
      if (kill(*it, 0) == 0) kill(*it, SIGKILL);
    }
    pids_.clear();
  }

  std::filesystem::path dir_;
  std::string hostname_;
  std::vector<pid_t> pids_;  // munged, slurmctld, slurmd, in start order
};

}  // namespace

TEST_CASE("Slurm sweep: a job array on a single-node Slurm gives the local sweep's load table", "[verification][sweep][slurm]") {
  SingleNodeSlurm slurm;
  const std::filesystem::path dir = testing::scratch_dir("sweep_slurm");
  const std::filesystem::path spec = write_small_sweep(dir);

  REQUIRE(run_fowtsim("sweep " + spec.string() + " --output-dir " + (dir / "local").string() + " --jobs 2", dir / "local.log") == 1);

  // Two cases per array task, at most two tasks at once (the node's two CPUs).
  const std::string slurm_sweep = spec.string() + " --output-dir " + (dir / "slurm").string();
  REQUIRE(run_fowtsim("sweep " + slurm_sweep + " --slurm --cases-per-task 2 --max-running 2", dir / "submit.log") == 0);
  const std::string submitted = read_text(dir / "submit.log");
  INFO(submitted);
  CHECK_THAT(read_text(dir / "slurm/slurm/sweep.sbatch"), Catch::Contains("#SBATCH --array=0-6%2"));
  std::smatch job;
  REQUIRE(std::regex_search(submitted, job, std::regex("submitted +job ([0-9]+)")));
  INFO(slurm.logs());
  REQUIRE(slurm.wait_for_job(job[1].str(), 300s));

  // The spec's set-up line ran in every array task (7 tasks of 2 cases), before its cases.
  CHECK_THAT(read_text(dir / "slurm/slurm/sweep.sbatch"), Catch::Contains("#SBATCH --comment=fowtsim-test"));
  for (int task = 0; task < 7; ++task) CHECK(std::filesystem::exists(dir / fmt::format("slurm/logs/setup-{}", task)));
  CHECK(run_fowtsim("sweep " + slurm_sweep + " --collect", dir / "collect.log") == 1);  // the blowup case fails there too
  CHECK_THAT(read_text(dir / "collect.log"), Catch::Contains("12 completed of 13"));
  // Every number of every case, the failure's exit code and reason included.
  CHECK(read_text(dir / "slurm/load_table.csv") == read_text(dir / "local/load_table.csv"));
}
