// `fowtsim bench startup`: seed 002 Sec. 5.6's computational-time benchmark — a 10-minute start-up
// of the land-based NREL 5MW turbine without controller or turbulence at Δt 0.01 s
// (inputs/nrel5mw/onshore_startup_rr.yaml: the Rayleigh–Ritz model with ElastoDyn's 15 DOFs),
// printed beside the seed's times for the other tools (their machines, not this one: a ratio to
// them is indicative only). Printed, never asserted.
#include <cstdio>
#include <filesystem>

#include <fmt/format.h>

#include "run/run_scene.hpp"
#include "verify/verify_cases.hpp"

namespace fowtsim::driver {

void bench_startup(std::FILE* out) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "fowtsim_bench_startup";
  std::filesystem::create_directories(dir);
  auto run = [&](const std::string& induction) {
    RunRequest r;
    r.deck_path = source_input("nrel5mw/onshore_startup_rr.yaml");
    r.output_base = dir / "startup";
    r.deck_settings = {"aero.induction=" + induction};
    return run_scene(r, nullptr);
  };
  const RunReport stage = run("stage"), step = run("step");
  fmt::print(out, "Seed 002 Sec. 5.6: 600 s start-up of the land-based NREL 5MW, no controller or turbulence, Δt 0.01 s\n");
  fmt::print(out, "{:<52} {:>10} {:>14}\n", "tool", "time [s]", "× real time");
  fmt::print(out, "{:<52} {:>10.2f} {:>14.1f}\n", "fowtsim, Rayleigh-Ritz (15 DOF), time loop", stage.wall_s, 600.0 / stage.wall_s);
  fmt::print(out, "{:<52} {:>10.2f} {:>14.1f}\n", "  the same, in all (deck, set-up, output)", stage.total_wall_s, 600.0 / stage.total_wall_s);
  fmt::print(out, "{:<52} {:>10.2f} {:>14.1f}\n", "  aero.induction: step (held over the RK4 stages)", step.wall_s, 600.0 / step.wall_s);
  const struct {
    const char* tool;
    double seconds;
  } seed[] = {{"FAST7 (single precision; seed's machine)", 25.0}, {"the seed's tool (RK4, 15 DOF)", 56.0},
              {"OpenFAST 2 (single precision)", 74.0},           {"HAWC2", 171.0},
              {"OpenFAST 2 (double precision)", 188.0}};
  for (const auto& s : seed) fmt::print(out, "{:<52} {:>10.0f} {:>14.1f}\n", s.tool, s.seconds, 600.0 / s.seconds);
  fmt::print(out, "(one run on this machine; the seed's times are from its machine)\n");
  std::filesystem::remove_all(dir);
}

}  // namespace fowtsim::driver
