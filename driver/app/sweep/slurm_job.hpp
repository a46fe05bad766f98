#pragma once
// A sweep as one Slurm job array: the script maps the array index to its cases (several per task
// when --cases-per-task > 1, as NREL packs short serial runs per node) and runs each with `fowtsim
// run`, writing its log and exit code where a local sweep would; `fowtsim sweep --collect` then
// reads the same files. Slurm's own accounting (sacct) is not needed for any of it.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "sweep/case_files.hpp"
#include "sweep/slurm_options.hpp"

namespace fowtsim::driver::sweep {


struct SlurmJob {
  std::filesystem::path script;     // slurm/sweep.sbatch
  std::filesystem::path case_list;  // slurm/cases.txt: one case name per line, task i runs lines i·P … i·P + P − 1
  int tasks = 0;                    // array size
};

// The spec's `slurm:` options with the command line's over them (a command-line value wins).
SlurmOptions merge_slurm_options(const SlurmOptions& spec, const SlurmOptions& command_line);

// Writes the script and the case list for `case_names` (the cases still to run).
SlurmJob write_slurm_job(const std::string& sweep_name, const SweepLayout& layout, const std::vector<std::string>& case_names,
                         const std::filesystem::path& executable, const SlurmOptions& options);

// The sbatch command line that submits the job.
std::vector<std::string> sbatch_command(const SlurmJob& job);

// Runs sbatch and returns the job id it prints (--parsable); throws InputError with sbatch's
// message if it fails or is not installed.
std::string submit_slurm_job(const SlurmJob& job);

}  // namespace fowtsim::driver::sweep
