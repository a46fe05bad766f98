#pragma once
// One point of the coupling-step stability map (`fowtsim bench stability`): the default deck
// (OC3 load case, MBBT blades) run with one coupling mode, pair of steps and tower, and what became
// of it.
#include <filesystem>
#include <string>
#include <vector>

namespace fowtsim::driver {

struct StabilityPoint {
  std::string mode;  // blades.coupling: multi_rate | predictor_corrector | single_rate
  double dt_large_s = 0.0, dt_small_s = 0.0;
  // structure.tower.flexible. Rigid: the multibody in RK4 steps of ≤ 20 ms inside ΔT (the map of the
  // blades' exchange as first measured); flexible: one RK4 step per ΔT, as the default deck.
  bool flexible_tower = false;
};

enum class StabilityVerdict {
  stable,       // ran to the end, finite, within the criteria below
  small_angle,  // stopped by the beam's small-angle guard: an accuracy limit of the beam scheme
  diverged,     // non-finite, or outside the criteria
};

// The README's criteria of a stable run: |platform pitch| below this, rotor speed in (0, this).
constexpr double kStablePitchDeg = 20.0, kStableRotorRpm = 25.0;

struct StabilityOutcome {
  StabilityVerdict verdict = StabilityVerdict::stable;
  double stopped_at_s = 0.0;  // when the run stopped or first left the criteria [s]; t_max if stable
  std::string reason;         // the error message or the criterion broken; empty if stable
  double max_abs_pitch_deg = 0.0, min_rotor_rpm = 0.0, max_rotor_rpm = 0.0;  // over the rows written
  double wall_s = 0.0;
  std::vector<std::string> warnings;  // the run's warnings (e.g. a blade tip outside the wind grid)
};

// Runs `deck` (the default deck, included as is) for t_max_s with the point's coupling and steps,
// writing <work_dir>/point.out (platform pitch and rotor speed at every large step), and
// classifies it.
StabilityOutcome run_stability_point(const StabilityPoint& point, const std::filesystem::path& deck, double t_max_s,
                                     const std::filesystem::path& work_dir);

}  // namespace fowtsim::driver
