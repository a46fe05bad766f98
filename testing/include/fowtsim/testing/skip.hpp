#pragma once
// Test-only helpers shared by every module's Catch2 executable.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <unistd.h>

namespace fowtsim::testing {

// CTest runs each TEST_CASE in its own process and registers exit code 4 as "skipped"
// (SKIP_RETURN_CODE in fowtsim_add_tests). Catch2 v2 has no skip of its own.
[[noreturn]] inline void skip(const std::string& why) {
  std::printf("SKIPPED: %s\n", why.c_str());
  std::fflush(stdout);
  std::_Exit(4);
}

// The shared reference directory (../shared); skips the test when it is absent.
inline std::filesystem::path shared_dir_or_skip() {
  const std::filesystem::path dir = FOWTSIM_SHARED_DIR;
  if (!std::filesystem::is_directory(dir / "reference")) {
    skip("shared reference data not found at " + dir.string());
  }
  return dir;
}

inline std::filesystem::path source_dir() { return FOWTSIM_SOURCE_DIR; }

// A fresh scratch directory for one test, under the build tree's working directory. The process id
// keeps apart test cases of one executable that ctest runs at once under the same name (seen: two
// flexible-rotor cases rewriting each other's deck while one read it).
inline std::filesystem::path scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::current_path() / "test-scratch" / (name + "." + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace fowtsim::testing
