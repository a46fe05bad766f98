#pragma once
// The small sweep the local and the Slurm tests both run: the rigid-blade OC3 turbine, 30 s per
// case (10 s transient + 20 s analysed), 12 cases of DLC 1.2 (3 speeds × 2 yaw × 2 seeds) on a
// coarse turbulence grid, and one case made to blow up (a generator inertia of 0.01 kg m² makes
// the drivetrain explicit-unstable: numerical failure, exit 3, within 0.1 s).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>

#include "fowtsim/testing/skip.hpp"

namespace fowtsim::sweep_test {

inline constexpr int kGoodCases = 12;

inline std::filesystem::path write_small_sweep(const std::filesystem::path& dir) {
  const std::filesystem::path spec = dir / "small_sweep.yaml";
  std::ofstream(spec) << "sweep:\n  name: small\n  base_deck: "
                      << (testing::source_dir() / "inputs/oc3_hywind/turbine_ntm_12mps_irregular.yaml").string() << R"(
  transient_s: 10
  analysis_s: 20
load_cases:
  - name: dlc12
    preset: dlc1.2
    wind_speeds_m_s: [8, 12, 16]
    yaw_misalignment_deg: [0, 8]
    seeds: 2
    sea_state:
      table:
        - {wind_speed_m_s: 4, hs_m: 1.0, tp_s: 6.0}
        - {wind_speed_m_s: 24, hs_m: 5.0, tp_s: 11.0}
    set: {wind.turbulence.ny: [7], wind.turbulence.nz: [7]}
  - name: blowup
    set: {structure.drivetrain.generator_inertia_kg_m2: [0.01], wind.turbulence.ny: [7], wind.turbulence.nz: [7]}
slurm:                       # --slurm only; a local sweep ignores it
  sbatch_lines: [--comment=fowtsim-test]
  setup_lines: ['touch "$root/logs/setup-$SLURM_ARRAY_TASK_ID"']
load_table:
  channels: [GenPwr, RotSpeed, PtfmPitch, TwrBsMyt]
  fatigue:
    - {channel: TwrBsMyt, wohler_exponent: 4}
)";
  return spec;
}

// The fowtsim executable built next to the test executable.
inline std::filesystem::path fowtsim_exe() {
  const auto exe = std::filesystem::read_symlink("/proc/self/exe").parent_path() / "fowtsim";
  if (!std::filesystem::exists(exe)) testing::skip("the fowtsim executable is not built next to the tests: " + exe.string());
  return exe;
}

// Runs `fowtsim args…` with stdout and stderr into `log`; returns the exit status.
inline int run_fowtsim(const std::string& args, const std::filesystem::path& log) {
  const std::string command = fowtsim_exe().string() + " " + args + " > " + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace fowtsim::sweep_test
