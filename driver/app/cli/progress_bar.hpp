#pragma once
// A one-line progress bar on a terminal (redrawn at most 10 times a second), silent otherwise.
#include <chrono>
#include <cstdio>

namespace fowtsim::driver {

class ProgressBar {
 public:
  explicit ProgressBar(std::FILE* stream);  // enabled only when stream is a terminal
  void update(double time_s, double t_max_s);
  void done();                              // clears the line

 private:
  std::FILE* stream_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace fowtsim::driver
