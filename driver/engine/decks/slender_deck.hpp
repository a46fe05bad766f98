#pragma once
// The deck of the slender-body scene (modules/slender, seed 004): the body as uniform segments cut
// into strips, its end supports and springs, top tension, damping and shape functions (`slender`),
// the water (`water`), a regular wave or a JONSWAP sea (`sea`) and what to solve (`analysis`).
// Its keys are listed by `fowtsim --help-deck` and in inputs/slender/.
#include <cstdint>
#include <string>
#include <vector>

#include "fowtsim/io/schema.hpp"
#include "fowtsim/slender/model.hpp"

namespace fowtsim::driver {

struct SlenderSea {
  bool regular = true;
  double height_m = 0.0, period_s = 0.0;           // regular: H = 2a, T
  double hs_m = 0.0, tp_s = 0.0, gamma = 3.3;      // jonswap
  std::uint64_t seed = 1;                          // jonswap: phases, std::mt19937_64
  double record_s = 0.0;                           // jonswap: Δω = 2π/record (the time record repeats after it)
  double min_omega_rad_s = 0.0, max_omega_rad_s = 0.0;  // jonswap: ω_j = jΔω within [min, max]
};

struct SlenderAnalysis {
  bool frequency_domain = true, time_domain = true;
  int modes = 0;                     // lowest modes kept (0: all)
  double transient_s = 0.0;          // time domain: discarded before the statistics
  std::vector<double> stations_m;    // time-series stations, x from the bottom end [m]
  double drag_tolerance = 1e-6;      // frequency domain: the drag linearisation's convergence on γ [-]
};

struct SlenderDeck {
  slender::BodyDescription body;
  slender::Environment environment;
  SlenderSea sea;
  SlenderAnalysis analysis;
};

// The keys `slender`, `water`, `sea`, `analysis` (the scene adds `simulation` and `output`).
std::vector<io::SchemaField> slender_deck_fields();

// Reads and cross-checks them (a station off the body, a period the time step does not divide, a
// transient that leaves no wave period of the simulated time, a regular-wave key in a JONSWAP sea …),
// errors located at file:line: key. time_step_s, t_max_s: the time domain's step and span.
SlenderDeck read_slender_deck(const io::ValidatedDeck& deck, double time_step_s, double t_max_s);

}  // namespace fowtsim::driver
