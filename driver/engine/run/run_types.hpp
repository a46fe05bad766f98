#pragma once
// What the command line asks of a run, and what a run reports back to it.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fowtsim::driver {

struct RunRequest {
  std::filesystem::path deck_path;                   // top-level scene deck
  std::optional<std::filesystem::path> output_base;  // -o: output path; a .h5/.out/.outb extension is
                                                     // honoured (see resolve_output_names)
  std::optional<std::string> output_format;          // --out-format h5|out|outb|both (overrides the deck)
  std::optional<double> t_max_s;                     // --tmax: overrides simulation.t_max_s [s]
  std::optional<double> dt_s;                        // --dt: beam runs' time step (BeamDyn DT, beam decks) [s]
  std::optional<int> beam_segments;                  // --segments: finite volumes per beam
  std::optional<std::string> beam_integrator;        // --integrator: generalized_alpha | erk
  std::optional<int> beam_matrix_max_age;            // --matrix-age: generalized-α step-matrix reuse
  std::optional<double> checkpoint_every_s;          // --checkpoint-every: write <output>.chk every T [s]
  std::optional<std::filesystem::path> restart_path; // --restart: continue from this checkpoint
  std::vector<std::string> deck_settings;            // --set key.path=value, in order (io::apply_settings)
  std::optional<std::filesystem::path> turbulence_cache;  // --turbulence-cache: a folder of generated wind
                                                     // fields that runs share (rotor/turbulence_cache.hpp)
};

struct RunReport {
  double simulated_s = 0.0;                    // simulated time reached [s]
  double wall_s = 0.0;                         // wall-clock time of the time loop [s]
  double total_wall_s = 0.0;                   // of the whole run: decks, set-up (turbulence, sea), loop, output [s]
  long large_steps = 0;                        // large steps taken
  int substeps = 1;                            // small steps per large step
  std::string coupling;                        // coupling mode; without a time loop, what was solved
  bool time_loop = true;                       // false: solved without stepping in time (a frequency-domain
                                               // solution): no simulated time, steps or real-time factor
  std::vector<std::filesystem::path> outputs;  // files written
  std::vector<std::string> warnings;           // shown in the summary
  std::vector<std::string> results;            // lines of results asked for by the deck (summary)
  int interrupted_by = 0;                      // signal that stopped the run early (0: it ran to the end)
  double t_max_s = 0.0;                        // simulated time the run was asked for [s]
};

// Called after every large step with the current and the final simulated time [s].
using ProgressCallback = std::function<void(double time_s, double t_max_s)>;

}  // namespace fowtsim::driver
