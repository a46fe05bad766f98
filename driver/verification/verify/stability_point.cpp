#include "verify/stability_point.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"
#include "run/run_scene.hpp"

namespace fowtsim::driver {

namespace {

// The beam's guard against steps too large for its piecewise-linear rotations
// (modules/beam/src/dynamic_stepper.cpp check_increments): it refuses a step whose incremental
// rotation exceeds a small angle, whatever the state, so it marks a step the scheme cannot take
// accurately, not a state that grew without bound.
bool is_small_angle_guard(const NumericalError& e) {
  return e.context().module == "beam" && e.context().variable == "incremental rotation";
}

// Fills the extremes of the rows written and, for the first row outside the criteria, marks the
// outcome diverged there (a row before a guard stop wins: the state left the criteria first).
void check_rows(const io::ChannelTable& rows, StabilityOutcome& outcome) {
  const auto& time = rows.time();
  const auto& pitch = rows.columns[rows.find("PtfmPitch").value()];
  const auto& rpm = rows.columns[rows.find("RotSpeed").value()];
  outcome.min_rotor_rpm = rpm.empty() ? 0.0 : rpm.front();
  outcome.max_rotor_rpm = outcome.min_rotor_rpm;
  for (std::size_t i = 0; i < time.size(); ++i) {
    outcome.max_abs_pitch_deg = std::max(outcome.max_abs_pitch_deg, std::abs(pitch[i]));
    outcome.min_rotor_rpm = std::min(outcome.min_rotor_rpm, rpm[i]);
    outcome.max_rotor_rpm = std::max(outcome.max_rotor_rpm, rpm[i]);
    std::string broken;
    if (!std::isfinite(pitch[i]) || !std::isfinite(rpm[i]))
      broken = "non-finite platform pitch or rotor speed";
    else if (std::abs(pitch[i]) >= kStablePitchDeg)
      broken = fmt::format("|platform pitch| {:.1f}° ≥ {}°", std::abs(pitch[i]), kStablePitchDeg);
    else if (rpm[i] <= 0.0 || rpm[i] >= kStableRotorRpm)
      broken = fmt::format("rotor speed {:.1f} rpm outside (0, {}) rpm", rpm[i], kStableRotorRpm);
    if (!broken.empty()) {
      outcome.verdict = StabilityVerdict::diverged;
      outcome.stopped_at_s = time[i];
      outcome.reason = broken;
      return;
    }
  }
}

}  // namespace

StabilityOutcome run_stability_point(const StabilityPoint& point, const std::filesystem::path& deck, double t_max_s,
                                     const std::filesystem::path& work_dir) {
  const auto point_deck = work_dir / "point.yaml";
  // Decimation 1: the criteria are checked at every large step, and a stopped run keeps them all.
  std::ofstream(point_deck) << "include: [" << std::filesystem::absolute(deck).string() << "]\n"
                            << fmt::format("simulation: {{t_max_s: {}, dt_s: {}}}\n", t_max_s, point.dt_large_s)
                            << "output: {format: out, decimation: 1, channels: [PtfmPitch, RotSpeed]}\n"
                            << fmt::format("structure: {{tower: {{flexible: {}}}, max_step_s: {}}}\n", point.flexible_tower,
                                           point.flexible_tower ? point.dt_large_s : 0.02)
                            << fmt::format("blades: {{coupling: {}, substeps: {}}}\n", point.mode,
                                           std::lround(point.dt_large_s / point.dt_small_s));
  RunRequest request;
  request.deck_path = point_deck;
  request.output_base = work_dir / "point";
  request.output_format = "out";

  StabilityOutcome outcome;
  outcome.stopped_at_s = t_max_s;
  const auto start = std::chrono::steady_clock::now();
  try {
    outcome.warnings = run_scene(request, nullptr).warnings;
  } catch (const NumericalError& e) {
    outcome.verdict = is_small_angle_guard(e) ? StabilityVerdict::small_angle : StabilityVerdict::diverged;
    outcome.stopped_at_s = e.context().time_s.value_or(0.0);
    outcome.reason = fmt::format("{}: {}", e.context().module, e.message());
  }
  outcome.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  check_rows(io::read_channels(work_dir / "point.out"), outcome);
  return outcome;
}

}  // namespace fowtsim::driver
