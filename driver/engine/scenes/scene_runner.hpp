#pragma once
// What the fixed-step scenes share: the `simulation` and `output` deck sections and the time loop
// that writes rows, reports progress and keeps every row written so far when a step fails.
#include <functional>
#include <span>
#include <vector>

#include "fowtsim/core/channels.hpp"
#include "fowtsim/io/output_sink.hpp"
#include "fowtsim/io/schema.hpp"
#include "run/checkpoint.hpp"
#include "run/run_types.hpp"

namespace fowtsim::driver {

io::Schema simulation_schema(const char* step_doc);  // t_max_s, dt_s
io::Schema output_schema();                          // format, decimation, channels

struct FixedStepScene {
  std::vector<ChannelInfo> written;                   // channels in file order
  io::RunMetadata metadata;                           // version, deck path and hash, dt filled in by run()
  std::function<void(double t, double dt)> step;      // advance from t to t + dt
  std::function<void(double t, std::span<double> row)> row;  // values of `written` at t
  // What the scene warns about at the end of the run (summary and HDF5); may be empty.
  std::function<void(std::vector<std::string>& warnings)> warnings;
  // The scene's whole changing state, for checkpoints and restarts (empty: not supported).
  std::function<void(CheckpointWriter&)> save;
  std::function<void(CheckpointReader&)> load;
};

// Runs t = 0, dt, …, t_max (deck or --tmax; dt must divide it, checked before any file is opened),
// writing every output.decimation-th row to the files the request and deck name. An exception
// during the run closes the files as "failed: …" (keeping every row so far) and propagates. A
// SIGINT/SIGTERM (run/interrupt.hpp) stops the loop at the end of the current step: the files are
// closed as "interrupted at t = …" and the report's interrupted_by names the signal.
RunReport run_fixed_steps(const RunRequest& request, const io::ValidatedDeck& deck, FixedStepScene scene,
                          const ProgressCallback& progress);

}  // namespace fowtsim::driver
