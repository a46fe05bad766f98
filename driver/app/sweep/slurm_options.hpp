#pragma once
// How a sweep's Slurm job array is submitted: from the spec's `slurm:` section, with the command
// line's options over it (merge_slurm_options in slurm_job.hpp).
#include <optional>
#include <string>
#include <vector>

namespace fowtsim::driver::sweep {

struct SlurmOptions {
  std::string partition;            // --partition; "" = the cluster's default
  std::string time_limit;           // --time per task (Slurm's format, e.g. 01:00:00); "" = default
  std::string account;              // --account charged for the job; "" = the user's default
  std::string qos;                  // --qos; "" = the association's default
  std::string memory;               // --mem per task (Slurm's format, e.g. 2G); "" = the partition's default
  std::vector<std::string> sbatch_lines;  // more options, each written as "#SBATCH <line>" (e.g. --constraint=avx2)
  std::vector<std::string> setup_lines;   // shell lines run before the cases (module load …, export …)
  int cases_per_task = 1;           // cases run one after the other in each array task
  std::optional<int> max_running;   // the %M of --array=0-N%M: tasks running at once
};

}  // namespace fowtsim::driver::sweep
