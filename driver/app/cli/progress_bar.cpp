#include "cli/progress_bar.hpp"

#include <string>
#include <unistd.h>

#include <fmt/format.h>

namespace fowtsim::driver {

ProgressBar::ProgressBar(std::FILE* stream)
    : stream_(stream), enabled_(isatty(fileno(stream)) != 0), start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

void ProgressBar::update(double time_s, double t_max_s) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < std::chrono::milliseconds(100) && time_s < t_max_s) return;
  last_draw_ = now;
  const double fraction = t_max_s > 0 ? std::min(1.0, time_s / t_max_s) : 1.0;
  const double wall = std::chrono::duration<double>(now - start_).count();
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(fraction * kWidth);
  fmt::print(stream_, "\r[{}{}] {:5.1f}%  t = {:.2f} / {:.2f} s  {:.1f}x real time ", std::string(filled, '#'),
             std::string(kWidth - filled, '.'), 100.0 * fraction, time_s, t_max_s, wall > 0 ? time_s / wall : 0.0);
  std::fflush(stream_);
}

void ProgressBar::done() {
  if (enabled_) fmt::print(stream_, "\r{}\r", std::string(79, ' '));
}

}  // namespace fowtsim::driver
