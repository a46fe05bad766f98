#pragma once
// The benchmark beams of seed 000 §2.5 (and seed 002 §5.2), built in BeamDyn's convention (local
// axis 3 along the beam), with their exact solutions where one exists. Shared by the tests and by
// `fowtsim verify beam-…`.
#include <vector>

#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/solvers.hpp"

namespace fowtsim::beam::benchmarks {

// A station with diagonal stiffness [κGA1, κGA2, EA, EI1, EI2, GJ], mass per length m on the
// reference line and diagonal rotary inertia per length (no offsets).
Station uniform_station(double eta, const Vec6& stiffness, double mass_per_length, const Vec3& rotary_inertia);

// §2.5.1: straight cantilever along z, length 1, bending stiffness 2 about x (and y), shear and
// axial stiffness 1e4 (stiff: the exact circle is inextensible), torsion 2. Unit mass per length.
BeamDefinition rollup_beam();
inline constexpr double kRollupLength = 1.0;
inline constexpr double kRollupBendingStiffness = 2.0;

// Exact position of the point at arclength s of a straight beam along z bent by a pure moment
// M about x with bending stiffness EI: an arc of curvature κ = M/EI (a rotation about +x turns
// z towards −y).
Vec3 rollup_exact_position(double s, double moment_x, double bending_stiffness);

// RMS over nodes of |x_n − exact circle(s_n)| of the roll-up beam with `segments` volumes under
// the seed's tip moment 4π = 2π EI/L (static solve): the measure of the seed's Fig. 2.5.
double rollup_rmse(int segments);

// §2.5.2 (Bathe–Bolourchi): 45° arc of radius 100 starting along z, bending towards +x (as the
// BeamDyn r-test bd_curved_beam), unit square section E = 1e7, G = 0.5e7, shear factor 5/6.
BeamDefinition curved_beam();

// Static tip position of curved_beam() under tip force F along +y, in the seed's axes (its arc
// starts along x and bends towards z: seed (x, y, z) = ours (z, y, x)).
Vec3 curved_beam_tip_seed_axes(int segments, double force_N);

// §2.5.1 time-step study: the 1 m steel strip 3.31 × 3.31 mm, E 200 GPa, G 79.3 GPa,
// ρ 7850 kg/m³, stiffness damping 1e-6 s, rolled up by its tip moment.
BeamDefinition steel_strip();
double steel_strip_rollup_moment();  // 2π EI / L (= 4π for EI ≈ 2): closes the circle [N·m]


// One row of the seed's Table 2.1: node positions at t_end with step dt compared with a reference
// run at a much smaller step.
struct TimeStepRow {
  double dt_s = 0.0;
  bool failed = false;          // the step broke the small-angle limit or diverged
  double rms_vs_reference = 0.0;  // RMS over nodes of |x_dt − x_ref| [m]
  double relative = 0.0;        // the same over RMS |x_ref − x_undeformed|
  double rms_vs_half = 0.0;     // RMS |x_dt − x_dt/2| [m] (NaN where dt/2 failed)
  double order = 0.0;           // log2 of successive rms_vs_half ratios (NaN on the last row)
  double wall_s = 0.0;          // wall time of the run at dt
};

// Table 2.1 for the steel strip under the suddenly applied closing moment, t_end = 0.0064 s.
// dts descending, each halving the previous; reference_dt much smaller (seed: 5e-6 s).
std::vector<TimeStepRow> strip_time_step_study(int segments, const DynamicOptions& options,
                                               const std::vector<double>& dts, double reference_dt);

}  // namespace fowtsim::beam::benchmarks
