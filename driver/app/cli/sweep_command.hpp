#pragma once
// `fowtsim sweep SPEC`: design-load-case sweeps (driver/app/sweep/README.md).
//   --list                  print the expanded cases (names, wind speeds, seeds, sea states)
//   --jobs N                run the cases still to run in N local processes, then write the load table
//   --slurm [--dry-run]     write the case decks and a job-array script, and submit it with sbatch
//   --collect               write the load table from whatever has finished
//   --frequency-domain      rank the cases by their frequency-domain screening (sweep/frequency_domain_screening.hpp)
#include <cstdio>
#include <filesystem>
#include <optional>

#include "sweep/slurm_job.hpp"

namespace fowtsim::driver {

struct SweepRequest {
  enum class Action { run_local, list, slurm, collect };
  std::filesystem::path spec;                       // the sweep spec (YAML)
  Action action = Action::run_local;                // what to do
  std::optional<std::filesystem::path> output_dir;  // overrides the spec's sweep.output_dir
  std::optional<std::filesystem::path> base_deck;   // overrides the spec's sweep.base_deck (the same cases, seeds
                                                    // and events on another model, e.g. the fastest one)
  int jobs = 1;                                     // local processes at once
  sweep::SlurmOptions slurm;                        // --slurm: partition, time, packing, throttle
  bool dry_run = false;                             // --slurm: write everything, do not submit
  bool frequency_domain = false;                    // screen every case in the frequency domain, run none
  std::filesystem::path executable;                 // runs the cases (`fowtsim run`); empty = this process's
};

// Returns the exit code: 0 every case completed (or listed, written, submitted), 1 some case did
// not (each is listed with its exit code and reason), 130/143 the local sweep was interrupted.
// Throws InputError (io::DeckError with file:line for the spec) for bad input.
int run_sweep_command(const SweepRequest& request, std::FILE* out);

}  // namespace fowtsim::driver
