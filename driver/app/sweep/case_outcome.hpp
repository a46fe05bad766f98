#pragma once
// What became of a case, read from its files alone (output attributes, exit code, log), so local
// runs, Slurm tasks and a later `--collect` all judge it the same way. A case counts as done only
// when its output says `completed` for the deck hash its deck has now (resume and collection).
#include <optional>
#include <string>

#include "sweep/case_files.hpp"

namespace fowtsim::driver::sweep {

enum class CaseState {
  completed,    // output status "completed", same deck hash
  failed,       // the run stopped on an error (exit code and message), or was killed
  interrupted,  // stopped by SIGINT/SIGTERM: runs again next time
  running,      // the output is still being written
  stale,        // an output of an earlier version of the case deck: runs again
  missing,      // not run yet
};

const char* state_name(CaseState state);

struct CaseOutcome {
  CaseState state = CaseState::missing;
  std::optional<int> exit_code;  // of `fowtsim run`, when it has ended
  std::string message;           // why it failed: its error line, or the output status
  double wall_time_s = 0.0;      // wall time of a completed run [s]
  double end_time_s = 0.0;       // simulated time reached [s]
};

CaseOutcome read_case_outcome(const SweepLayout& layout, const std::string& case_name, const std::string& deck_hash);

// Root attributes of a fowtsim HDF5 output that tell how its run ended (hdf5_writer.hpp).
struct RunAttributes {
  std::string status;     // "completed", "failed: …", "interrupted at …", "running"
  std::string deck_hash;  // FNV-1a of the deck and its includes
  std::optional<double> wall_time_s, end_time_s;  // written at the end of the run
};
// Throws fowtsim::Error naming the file if it is no readable HDF5 file.
RunAttributes read_run_attributes(const std::filesystem::path& h5);

}  // namespace fowtsim::driver::sweep
