// Cases die with their pool (issue 22, item 2): a pool killed outright (SIGKILL, no chance to
// forward anything) must not leave its cases running as orphans that write the outputs a rerun
// writes. Each case gets SIGTERM when its pool dies (the parent-death signal).
#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "fowtsim/testing/skip.hpp"
#include "sweep/local_pool.hpp"
#include "sweep_test_spec.hpp"

using namespace fowtsim;

namespace {

// Whether `pid` still runs (a zombie waiting for a reaper has ended).
bool running(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string pid_text, name, state;
  return stat >> pid_text >> name >> state && state != "Z";
}

}  // namespace

TEST_CASE("sweep pool: a pool killed with SIGKILL takes its running cases down with it", "[unit][sweep]") {
  const std::filesystem::path dir = testing::scratch_dir("sweep_pool_death");
  const std::filesystem::path pid_file = dir / "case.pid";
  std::filesystem::remove(pid_file);
  // The case: a shell that writes its pid, then waits long enough to outlive the test if it survives.
  const driver::sweep::CaseCommand command{"sleeper", {"-c", "echo $$ > " + pid_file.string() + "; exec sleep 60"}, dir / "sleeper.log", 60.0};

  const pid_t pool = fork();
  REQUIRE(pool >= 0);
  if (pool == 0) {
    driver::sweep::run_pool("/bin/sh", {command}, 1, [](const auto&) {}, [](const auto&) {});
    _exit(0);
  }
  pid_t case_pid = 0;
  for (int i = 0; i < 100 && case_pid == 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    std::ifstream(pid_file) >> case_pid;
  }
  REQUIRE(case_pid > 0);
  REQUIRE(running(case_pid));

  kill(pool, SIGKILL);
  waitpid(pool, nullptr, 0);
  const auto killed = std::chrono::steady_clock::now();
  while (running(case_pid) && std::chrono::steady_clock::now() - killed < std::chrono::seconds(5))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const double after_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - killed).count();
  INFO("the case was still running " << after_s << " s after its pool was killed");
  CHECK_FALSE(running(case_pid));
  if (running(case_pid)) kill(case_pid, SIGKILL);  // do not leave it behind when the check fails
}
