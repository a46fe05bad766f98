// The sweep folder lock (issue 22, item 2): one sweep per output folder, the holder named, no
// stale lock after a holder dies, and a rerun that waits for the cases a dead pool left running.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <optional>
#include <thread>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/testing/skip.hpp"
#include "sweep/folder_lock.hpp"
#include "sweep_test_spec.hpp"

using namespace fowtsim;
using driver::sweep::SweepFolderLock;
using sweep_test::read_text;

namespace {

// Forks a "pool" that takes the lock on `folder`, starts a "case" keeping the lock's descriptor
// for `case_s` seconds, and dies at once: the holder is dead, its case still holds the lock.
// Returns when the pool has died.
void leave_orphan_holding(const std::filesystem::path& folder, double case_s) {
  const pid_t pool = fork();
  REQUIRE(pool >= 0);
  if (pool == 0) {
    SweepFolderLock lock(folder, "test pool", stdout, std::chrono::milliseconds(0));
    if (fork() == 0) {  // the case: the inherited descriptor keeps the lock
      std::this_thread::sleep_for(std::chrono::duration<double>(case_s));
      _exit(0);
    }
    _exit(0);
  }
  int status = 0;
  waitpid(pool, &status, 0);
  REQUIRE(WIFEXITED(status));
}

}  // namespace

TEST_CASE("sweep folder lock: one holder at a time, named in the lock file and in the refusal", "[unit][sweep]") {
  const std::filesystem::path folder = testing::scratch_dir("sweep_lock_exclusive") / "out";
  std::optional<SweepFolderLock> first;
  first.emplace(folder, "fowtsim sweep a.yaml (local pool)", stdout);
  const std::string text = read_text(SweepFolderLock::file(folder));
  CHECK_THAT(text, Catch::StartsWith(fmt::format("pid={} host=", getpid())));
  CHECK_THAT(text, Catch::Contains("command=fowtsim sweep a.yaml (local pool)"));

  // A second sweep (here a second open file in the same process, which flock treats the same way)
  // is refused at once, naming the holder, and leaves the lock file as it was.
  const auto start = std::chrono::steady_clock::now();
  try {
    SweepFolderLock second(folder, "fowtsim sweep b.yaml (collect)", stdout);
    FAIL("the second lock was granted");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains(fmt::format("in use by another sweep (pid={} ", getpid())));
    CHECK_THAT(e.what(), Catch::Contains("nothing was changed"));
  }
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(1));  // a live holder: no waiting
  CHECK(read_text(SweepFolderLock::file(folder)) == text);

  // Released with its holder: the next sweep gets it and names itself.
  first.reset();
  const SweepFolderLock third(folder, "fowtsim sweep c.yaml (local pool)", stdout);
  CHECK_THAT(read_text(SweepFolderLock::file(folder)), Catch::Contains("command=fowtsim sweep c.yaml (local pool)"));
}

TEST_CASE("sweep folder lock: a dead pool's cases hold it until they end and a rerun waits for them (bounded)", "[unit][sweep]") {
  const std::filesystem::path folder = testing::scratch_dir("sweep_lock_orphans") / "out";

  // The orphan ends within the wait: the rerun gets the lock after it, not before.
  leave_orphan_holding(folder, 0.6);
  const auto start = std::chrono::steady_clock::now();
  const std::optional<SweepFolderLock> rerun(std::in_place, folder, "rerun", stdout, std::chrono::seconds(10));
  const double waited_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  INFO("waited " << waited_s << " s");
  CHECK(waited_s > 0.3);   // the orphan held it for 0.6 s after its pool died
  CHECK(waited_s < 5.0);   // and released it when it ended
}

TEST_CASE("sweep folder lock: an orphan that outlasts the wait stops the rerun naming the dead pool", "[unit][sweep]") {
  const std::filesystem::path folder = testing::scratch_dir("sweep_lock_orphan_stays") / "out";
  leave_orphan_holding(folder, 3.0);
  const std::string holder = read_text(SweepFolderLock::file(folder));
  try {
    SweepFolderLock rerun(folder, "rerun", stdout, std::chrono::milliseconds(300));
    FAIL("the lock was granted while the orphan held it");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains("still locked by cases of the sweep PID"));
    CHECK_THAT(e.what(), Catch::Contains("fuser -v"));
  }
  CHECK(read_text(SweepFolderLock::file(folder)) == holder);  // nothing changed
}
