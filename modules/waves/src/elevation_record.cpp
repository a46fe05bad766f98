#include "fowtsim/waves/elevation_record.hpp"

#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::waves {
namespace {

// "source:line" of sample j when the lines are known, else "source: sample j" (0-based).
std::string where(const ElevationRecord& r, std::size_t j) {
  if (r.lines.size() == r.time_s.size() && j < r.lines.size()) return fmt::format("{}:{}", r.source, r.lines[j]);
  return fmt::format("{}: sample {}", r.source, j);
}

[[noreturn]] void bad(const std::string& message) {
  throw InputError({"waves", std::nullopt, "waves.file",
                    "a record of uniformly spaced (time s, elevation m) samples at x = y = 0"},
                   message);
}

}  // namespace

RecordGrid check_elevation_record(const ElevationRecord& r) {
  const std::size_t n = r.time_s.size();
  if (r.elevation_m.size() != n)
    bad(fmt::format("{}: {} times but {} elevations", r.source, n, r.elevation_m.size()));
  if (n < kMinRecordSamples)
    bad(fmt::format("{}: the record needs at least {} samples (time s, elevation m), found {}", r.source,
                    kMinRecordSamples, n));
  for (std::size_t j = 0; j < n; ++j) {
    if (!std::isfinite(r.time_s[j]))
      bad(fmt::format("{}: time is {}, expected a finite number of seconds", where(r, j), r.time_s[j]));
    if (!std::isfinite(r.elevation_m[j]))
      bad(fmt::format("{}: elevation is {} at t = {:.9g} s, expected a finite number of metres", where(r, j),
                      r.elevation_m[j], r.time_s[j]));
  }
  RecordGrid grid;
  grid.samples = n;
  grid.start_s = r.time_s.front();
  // Step from the end points: it averages the rounding of printed times over the whole record.
  grid.step_s = (r.time_s.back() - grid.start_s) / static_cast<double>(n - 1);
  if (!(grid.step_s > 0.0))
    bad(fmt::format("{}: times must increase, found t = {:.9g} s on the last sample and {:.9g} s on the first",
                    where(r, n - 1),
                    r.time_s.back(), grid.start_s));
  const double slack = kUniformSamplingSlack * grid.step_s;
  for (std::size_t j = 1; j < n; ++j) {
    const double step = r.time_s[j] - r.time_s[j - 1];
    const double expected = grid.start_s + static_cast<double>(j) * grid.step_s;
    if (std::abs(step - grid.step_s) > slack || std::abs(r.time_s[j] - expected) > slack)
      bad(fmt::format("{}: time {:.9g} s is {:.9g} s after the previous sample; expected uniform sampling: "
                      "t = {:.9g} s, steps of {:.9g} s (first to last sample / {}) within {} % of a step",
                      where(r, j), r.time_s[j], step, expected, grid.step_s, n - 1, 100.0 * kUniformSamplingSlack));
  }
  grid.duration_s = static_cast<double>(n) * grid.step_s;
  return grid;
}

ElevationRecord make_elevation_record(std::span<const double> time_s, std::span<const double> elevation_m,
                                      std::string source) {
  ElevationRecord r;
  r.time_s.assign(time_s.begin(), time_s.end());
  r.elevation_m.assign(elevation_m.begin(), elevation_m.end());
  r.source = std::move(source);
  return r;
}

}  // namespace fowtsim::waves
