// `fowtsim bench aero` (rotor aerodynamics and turbulence generation, issue 4) and `fowtsim bench
// multibody` (one large step of the rigid multibody and one controller call, issue 6). Printed,
// never asserted: one run on this machine, compare as ratios.
#include <cstdio>
#include <filesystem>

#include <fmt/format.h>

#include "verify/reports.hpp"
#include "decks/aero_deck.hpp"
#include "fowtsim/aero/benchmarks.hpp"
#include "fowtsim/control/benchmark.hpp"
#include "fowtsim/io/schema.hpp"
#include "fowtsim/multibody/benchmark.hpp"
#include "fowtsim/wind/benchmarks.hpp"

namespace fowtsim::driver {

std::filesystem::path source_input(const std::string& relative);  // verify_cases.cpp

void bench_aero(std::FILE* out) {
  const auto deck_path = source_input("nrel5mw/aero.yaml");
  if (!std::filesystem::exists(deck_path)) {
    fmt::print(out, "(NREL 5MW aero deck not found at {}: run from the source tree)\n", deck_path.string());
  } else {
    const io::ValidatedDeck deck = io::read_deck(io::Schema::map({{"aero", aero_schema()}, {"airfoils", airfoils_schema()}}), deck_path);
    fmt::print(out, "NREL 5MW rotor, one aerodynamic evaluation (BEM at every node + rotor sums), 11 m/s, 11.87 rpm\n");
    const auto rows = aero::benchmarks::rotor_evaluation_bench(aero_params(deck), 4000);
    const std::size_t w = name_width(rows, [](const auto& r) { return r.name; });
    fmt::print(out, "{:<{}} {:>7} {:>6} {:>12} {:>10} {:>16} {:>10}\n", "case", w, "blades", "nodes", "µs/rotor", "µs/node",
               "R(φ) calls/node", "power kW");
    for (const auto& r : rows)
      fmt::print(out, "{:<{}} {:>7} {:>6} {:>12.1f} {:>10.2f} {:>16.1f} {:>10.1f}\n", r.name, w, r.blades, r.nodes_per_blade,
                 r.us_per_evaluation, r.us_per_node, r.residual_calls_per_node, r.power_W / 1e3);
  }
  fmt::print(out, "\nTurbulence: the OC3 deck's TurbSim field (IEC Kaimal NTM class B, 12 m/s at 90 m, 31×31, 630 s at 20 Hz)\n");
  const auto wind_rows = wind::bench_wind(1.0, 1'000'000);
  const std::size_t w = name_width(wind_rows, [](const auto& r) { return r.name; });
  fmt::print(out, "{:<{}} {:>9} {:>9} {:>10}  {}\n", "case", w, "wall [s]", "CPU [s]", "µs/call", "details");
  for (const auto& r : wind_rows)
    fmt::print(out, "{:<{}} {:>9.2f} {:>9.2f} {:>10.3f}  {}\n", r.name, w, r.wall_time_s, r.cpu_time_s, r.microseconds_per_call, r.details);
  fmt::print(out, "(TurbSim took 1,657 s of CPU for the same grid on this kind of machine: openfast-runs/NOTES.md)\n");
}

void bench_multibody(std::FILE* out) {
  fmt::print(out, "OC3-Hywind multibody, free (no gravity, no loads), rotor at 12.1 rpm: one large step of RK4\n");
  const auto rows = multibody::bench_multibody(20000);
  const std::size_t w = name_width(rows, [](const auto& r) { return r.name; });
  fmt::print(out, "{:<{}} {:>7} {:>8} {:>9} {:>10} {:>12} {:>12} {:>12}\n", "case", w, "steps", "ΔT [s]", "substeps", "µs/step",
             "µs/EoM eval", "µs/outputs", "|ΔE|/E");
  for (const auto& r : rows)
    fmt::print(out, "{:<{}} {:>7} {:>8.3f} {:>9} {:>10.2f} {:>12.2f} {:>12.2f} {:>12.1e}\n", r.name, w, r.steps, r.dt_s, r.substeps,
               r.us_per_step, r.us_per_evaluation, r.us_per_outputs, r.energy_drift);
  fmt::print(out, "\nController, one advance + outputs call (ΔT = 0.0125 s, generator speed crossing regions 2 to 3)\n");
  const auto control_rows = control::bench_control("", 200000);
  const std::size_t wc = name_width(control_rows, [](const auto& r) { return r.name; });
  fmt::print(out, "{:<{}} {:>9} {:>10}\n", "case", wc, "calls", "ns/call");
  for (const auto& r : control_rows) fmt::print(out, "{:<{}} {:>9} {:>10.0f}\n", r.name, wc, r.calls, r.ns_per_call);
  fmt::print(out, "(one run on this machine: compare as ratios)\n");
}

}  // namespace fowtsim::driver
