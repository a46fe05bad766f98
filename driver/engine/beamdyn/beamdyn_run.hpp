#pragma once
// `fowtsim run bd_driver.inp`: run a BeamDyn stand-alone driver case with the MBBT beam and write
// BeamDyn's channels (rows at the same times BeamDyn writes them, so `fowtsim compare` lines up).
#include <string>
#include <vector>

#include "fowtsim/beam/solvers.hpp"
#include "run/run_types.hpp"

namespace fowtsim::driver {

// True if the file is a BeamDyn driver input (its first line names the BeamDyn driver).
bool is_beamdyn_driver_file(const std::filesystem::path& path);

RunReport run_beamdyn_case(const RunRequest& request, const ProgressCallback& progress);

struct BeamDynSetup;

// How to run one clamped beam (a BeamDyn case or a YAML beam scene).
struct SingleBeamRun {
  int segments = 48;
  std::string integrator = "generalized_alpha";
  int matrix_max_age = beam::DynamicOptions{}.matrix_max_age;  // generalized-α step-matrix reuse
  std::vector<std::string> channels;  // BeamDyn channel names to write; empty = all
  bool skip_unknown_channels = true;  // BeamDyn OutList: warn and skip; YAML decks check before
  long decimation = 1;                // write every k-th step
  std::string scene;                  // recorded in the output metadata
  std::string deck_hash;
};
// Runs the beam through the common time loop (scenes/scene_runner.hpp): interruption by a
// signal, failure handling; no checkpoints.
RunReport run_single_beam(const BeamDynSetup& setup, const SingleBeamRun& how, const RunRequest& request,
                          const ProgressCallback& progress);

// One dynamic step of a BeamDyn case from t to t + dt: the case's input at the stepper's input
// time, then the step.
void step_beamdyn(const BeamDynSetup& setup, const beam::BeamModel& model, beam::DynamicStepper& stepper, double t_s,
                  double dt_s, beam::BeamInput& input, beam::BeamState& state);

}  // namespace fowtsim::driver
