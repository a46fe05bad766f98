#pragma once
// Seed 000 §3.5.3: the top-tensioned production riser conveying oil, its four cases (a)–(d) and
// what Figs. 3.11–3.12 show: deformed shapes at chosen instants and the envelope of the largest
// bending moment along the length. PIPE.md has the numbers and what the seed leaves open.
//
// The seed's riser: OD 254 mm, ID 228.6 mm, 300 m unstretched, E 209 GPa, ν 0.3, steel 7800 kg/m³,
// stiffness damping μ_K 0.001 s; oil 900 kg/m³, 0.009 Pa·s, roughness 0.05 mm, 2.242 m/s
// (50,000 bbl/day), wellhead pressure 20.68 MPa; Morison C_m 1.8, C_d 1.0; gravity, buoyancy;
// clamped at the wellhead and at the deck; 100 volumes, Δt 1 ms. What the seed does not give and
// we take: sea water 1025 kg/m³ at rest, g = 9.81 m/s², the riser spanning a 300 m water column
// (bottom at z = −300 m, top at the still-water level z = 0: every volume wet), the top moved up
// (stretch) and along y (sway), and the run starting from the static equilibrium under gravity,
// buoyancy and the internal pressure with the top in place.
//   (a) stretch 0.3 m over 1 s (eq. 3.66) and sway 5 sin(0.2π (t − 1)) from t = 1 s (eq. 3.67), flowing;
//   (b) as (a) without the stretch;
//   (c) as (b) with the top valve closed: no flow, the wellhead pressure at the bottom;
//   (d) as (b) with the bottom valve closed: no flow, atmospheric (zero gauge) pressure at the top.
#include <vector>

#include "fowtsim/beam/pipe.hpp"
#include "fowtsim/beam/solvers.hpp"
#include "fowtsim/beam/surrounding_water.hpp"
#include "fowtsim/beam/tip_motion.hpp"

namespace fowtsim::beam::riser {

struct RiserSetup {
  PipeDefinition pipe;        // root = wellhead (bottom), tip = deck (top), flow from root to tip
  SurroundingWater water;
  RampAndSway top;            // the top's prescribed motion
  Vec3 gravity_m_s2{0.0, 0.0, -9.81};
};

// Case 'a', 'b', 'c' or 'd' (throws std::invalid_argument otherwise).
RiserSetup seed_case(char which);

// The discretised riser (pipe, flow and water).
BeamModel riser_model(const RiserSetup& setup, int segments);

// The riser's input at time t: gravity and the top's prescribed motion.
void riser_input(const RiserSetup& setup, double t_s, BeamInput& input);

struct RiserRun {
  std::vector<double> snapshot_times_s;          // the instants asked for
  std::vector<std::vector<Vec3>> snapshots_m;    // bottom point, node positions, top point at each [m]
  std::vector<double> section_s_m;               // arclength of each section from the bottom [m]
  std::vector<double> max_bending_moment_n_m;    // envelope: largest |M| of each section over the run [N·m]
  double max_bending_moment_n_m_overall = 0.0;   // the envelope's largest value [N·m]
  double max_deflection_m = 0.0;                 // largest distance of a node from the chord between the
                                                 // (moved) ends, over the run [m]
  double final_mid_sway_m = 0.0;                 // the middle node's displacement along the sway direction at t_end [m]
  int steps = 0;
};

// Static equilibrium at t = 0, then generalized-α steps of dt to t_end (ρ∞ `spectral_radius`).
// The envelope and deflection are sampled every `sample_every` steps and at the snapshots.
// Throws NumericalError when a step fails (an unstable Δt).
RiserRun simulate(const RiserSetup& setup, int segments, double dt_s, double t_end_s,
                  const std::vector<double>& snapshot_times_s, int sample_every = 10, double spectral_radius = 0.0);

// |M| of each section (elastic bending moment, section frame) of a state [N·m].
void bending_moments(const BeamModel& model, const BeamState& state, std::vector<double>& out);

}  // namespace fowtsim::beam::riser
