#include "sweep/slurm_job.hpp"

#include <sys/wait.h>

#include <cstdio>
#include <fstream>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::driver::sweep {

namespace fs = std::filesystem;

namespace {

// Single-quoted for bash: safe for any path.
std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

SlurmOptions merge_slurm_options(const SlurmOptions& spec, const SlurmOptions& command_line) {
  SlurmOptions merged = command_line;
  auto fill = [](std::string& value, const std::string& from_spec) {
    if (value.empty()) value = from_spec;
  };
  fill(merged.partition, spec.partition);
  fill(merged.time_limit, spec.time_limit);
  fill(merged.account, spec.account);
  fill(merged.qos, spec.qos);
  fill(merged.memory, spec.memory);
  merged.sbatch_lines.insert(merged.sbatch_lines.begin(), spec.sbatch_lines.begin(), spec.sbatch_lines.end());
  merged.setup_lines.insert(merged.setup_lines.begin(), spec.setup_lines.begin(), spec.setup_lines.end());
  return merged;
}

SlurmJob write_slurm_job(const std::string& sweep_name, const SweepLayout& layout, const std::vector<std::string>& case_names,
                         const fs::path& executable, const SlurmOptions& options) {
  SlurmJob job;
  const fs::path dir = fs::absolute(layout.slurm_dir());
  fs::create_directories(dir);
  job.script = dir / "sweep.sbatch";
  job.case_list = dir / "cases.txt";
  const int per_task = std::max(1, options.cases_per_task);
  job.tasks = static_cast<int>((case_names.size() + static_cast<std::size_t>(per_task) - 1) / static_cast<std::size_t>(per_task));
  {
    std::ofstream list(job.case_list, std::ios::trunc);
    for (const std::string& name : case_names) list << name << "\n";
  }
  const fs::path root = fs::absolute(layout.root);
  std::string s = "#!/bin/bash\n";
  s += fmt::format("# fowtsim sweep {}: {} cases, {} per array task. Written by `fowtsim sweep --slurm`;\n"
                   "# collect the results with `fowtsim sweep SPEC --collect`.\n",
                   sweep_name, case_names.size(), per_task);
  s += fmt::format("#SBATCH --job-name=fowtsim-{}\n", sweep_name);
  s += fmt::format("#SBATCH --array=0-{}{}\n", job.tasks - 1, options.max_running ? fmt::format("%{}", *options.max_running) : "");
  s += "#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=1\n";
  s += fmt::format("#SBATCH --output={}\n", (dir / "slurm-%A_%a.log").string());
  if (!options.partition.empty()) s += fmt::format("#SBATCH --partition={}\n", options.partition);
  if (!options.time_limit.empty()) s += fmt::format("#SBATCH --time={}\n", options.time_limit);
  if (!options.account.empty()) s += fmt::format("#SBATCH --account={}\n", options.account);
  if (!options.qos.empty()) s += fmt::format("#SBATCH --qos={}\n", options.qos);
  if (!options.memory.empty()) s += fmt::format("#SBATCH --mem={}\n", options.memory);
  for (const std::string& line : options.sbatch_lines) s += fmt::format("#SBATCH {}\n", line);
  s += "set -u\n";
  s += fmt::format("root={}\nfowtsim={}\nper_task={}\n", shell_quote(root.string()), shell_quote(executable.string()), per_task);
  s += fmt::format("mapfile -t cases < {}\n", shell_quote(job.case_list.string()));
  // Set-up lines (modules, environment; they may use $root) run in the task's shell before any
  // case: a failing one is reported in the task's log and the cases still run, so that their own
  // logs say what went wrong.
  for (const std::string& line : options.setup_lines) s += line + "\n";
  s += "first=$((SLURM_ARRAY_TASK_ID * per_task))\n"
       "for ((i = first; i < first + per_task && i < ${#cases[@]}; i++)); do\n"
       "  case_name=${cases[i]}\n"
       "  rm -f \"$root/logs/$case_name.exit\"\n"
       "  \"$fowtsim\" run \"$root/decks/$case_name.yaml\" -o \"$root/cases/$case_name.h5\" > \"$root/logs/$case_name.log\" 2>&1\n"
       "  echo $? > \"$root/logs/$case_name.exit\"\n"
       "done\n";
  std::ofstream(job.script, std::ios::trunc) << s;
  fs::permissions(job.script, fs::perms::owner_exec | fs::perms::group_exec, fs::perm_options::add);
  return job;
}

std::vector<std::string> sbatch_command(const SlurmJob& job) { return {"sbatch", "--parsable", job.script.string()}; }

std::string submit_slurm_job(const SlurmJob& job) {
  std::string command;
  for (const std::string& word : sbatch_command(job)) command += shell_quote(word) + " ";
  command += "2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) throw InputError({"sweep", std::nullopt, "--slurm", "install Slurm's client (sbatch)"}, "cannot run sbatch");
  std::string output;
  char buffer[256];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  const int status = pclose(pipe);
  while (!output.empty() && (output.back() == '\n' || output.back() == '\r')) output.pop_back();
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw InputError({"sweep", std::nullopt, "--slurm", "check the partition and time limit, or use --dry-run and submit by hand"},
                     fmt::format("sbatch failed{}: {}", WIFEXITED(status) && WEXITSTATUS(status) == 127 ? " (not installed?)" : "", output));
  // --parsable prints "jobid" or "jobid;cluster".
  return output.substr(0, output.find(';'));
}

}  // namespace fowtsim::driver::sweep
