#pragma once
// The one production time loop of fowtsim (every scene and the BeamDyn driver cases run through
// it), and the `simulation` and `output` deck sections of the fixed-step scenes: the loop writes
// rows, reports progress, writes checkpoints, stops on SIGINT/SIGTERM and keeps every row written
// so far when a step fails.
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fowtsim/core/channels.hpp"
#include "fowtsim/io/output_sink.hpp"
#include "fowtsim/io/schema.hpp"
#include "run/checkpoint.hpp"
#include "run/output_set.hpp"
#include "run/run_types.hpp"

namespace fowtsim::driver {

// The `simulation` section of the fixed-step scenes (the floating and platform scenes).
struct SimulationKeys {
  double t_max_s = 600.0;  // simulated time [s]
  double dt_s = 0.05;      // the scene's step (the large step where there are two) [s]
};
io::Schema simulation_schema(const char* step_doc);
SimulationKeys simulation_keys(const io::ValidatedDeck& deck);  // of the deck's `simulation` section

// The `output` section of every scene (optional: absent = HDF5, every row, every channel).
struct OutputKeys {
  std::string format = "h5";                              // h5 | out | both
  int decimation = 1;                                     // write every k-th step
  std::optional<std::vector<std::string>> channels;      // absent = all
};
io::Schema output_schema();
OutputKeys output_keys(const io::ValidatedDeck& deck);  // of the deck's `output` section, or the defaults

struct FixedStepScene {
  std::vector<ChannelInfo> written;                   // channels in file order
  io::RunMetadata metadata;                           // the version is filled in by the loop
  std::function<void(double t, double dt)> step;      // advance from t to t + dt
  std::function<void(double t, std::span<double> row)> row;  // values of `written` at t
  // What the scene warns about at the end of the run (summary and HDF5); may be empty.
  std::function<void(std::vector<std::string>& warnings)> warnings;
  // What its inputs warn about before the first step (implausible values, records shorter than the
  // run): in the summary and the outputs even of a run that fails.
  std::vector<std::string> input_warnings;
  // The scene's whole changing state, for checkpoints and restarts (empty: not supported).
  std::function<void(CheckpointWriter&)> save;
  std::function<void(CheckpointReader&)> load;
  // Tables the scene computed before the loop, written and owned with the time series.
  std::vector<WholeFile> whole_files;
  // Tables complete only when the run is (statistics over the whole run): their suffixes, named
  // before the loop, and their bytes (one per suffix), asked for once the last step is taken. An
  // interrupted or failed run writes none and removes an earlier run's (OutputSet::write_end_files).
  std::vector<std::string> end_file_suffixes;
  std::function<std::vector<std::string>()> end_files;
};

// The time axis and the files of a run: rows at t0, t0 + dt, …, t0 + steps·dt.
struct FixedStepPlan {
  double t0_s = 0.0;
  double dt_s = 0.0;
  long steps = 0;
  double t_max_s = 0.0;        // the end the run was asked for (progress, report)
  std::string format = "h5";   // h5 | out | both
  long decimation = 1;         // write every k-th step
  std::filesystem::path base;  // output files without their extension
  std::string deck_hash;       // ties checkpoints to the deck
};

// The output part of a plan (format, decimation, files, deck hash) from the request and the
// deck's optional `output` section; the time axis is the caller's.
FixedStepPlan output_plan(const RunRequest& request, const io::ValidatedDeck& deck);

// A deck with simulation.t_max_s (or --tmax) and simulation.dt_s: dt must divide the simulated
// time, checked before any file is opened. The metadata gets the absolute deck path, its hash and
// dt as both steps.
RunReport run_fixed_steps(const RunRequest& request, const io::ValidatedDeck& deck, FixedStepScene scene,
                          const ProgressCallback& progress);

// Runs the plan, writing the row at t0 and every decimation-th step after it to the files the
// plan names. An exception during the run closes the files as "failed: …" (keeping every row so
// far) and propagates. A SIGINT/SIGTERM (run/interrupt.hpp) stops the loop at the end of the
// current step: the files are closed as "interrupted at t = …" and the report's interrupted_by
// names the signal.
RunReport run_fixed_steps(const RunRequest& request, const FixedStepPlan& plan, FixedStepScene scene,
                          const ProgressCallback& progress);

}  // namespace fowtsim::driver
