#pragma once
// A riser or dynamic power cable hung from the floating platform (issue 26, its last part): the
// deck's `riser:` section, and the glue between the rigid multibody (large step ΔT) and the line,
// the MBBT pipe of modules/beam (PIPE.md) at the small step Δt = ΔT/n.
//
// The line is resolved in the inertial frame g (the beam's floating frame f = g: no frame loads,
// and the still water, current and gravity of beam::SurroundingWater are those of g). Its root is
// the anchor on the seabed (clamped or pinned), its tip the hang-off point on the platform, held
// by a pin (a flex joint: no moment, so the platform's rotation needs no orientation at the top;
// beam::BeamInput moves a held tip by translation only). Per large step [T, T + ΔT], the same
// staggered multi-rate exchange as the flexible blades (coupling/multi_rate_scheduler.hpp,
// DESIGN.md §4), a light line on a heavy body:
//  1. the multibody advances with the line's top load averaged over the previous large step,
//     held in g as a force at the hang-off point, whose arm turns with the platform at every
//     Runge–Kutta stage (add_stage_loads);
//  2. the line takes n small steps with its top moved through the hang-off point's motion,
//     interpolated between T and T + ΔT as a cubic Hermite of the point's positions and velocities
//     at both ends (third order; its velocity the Hermite's derivative, consistent with the path);
//  3. its top load is averaged over the large step with the trapezoidal weights of the scheduler
//     (½, 1, …, 1, ½) and held over the next one.
// Steps 2–3 repeat multi_rate_step's fast loop (the multi_rate mode, no corrector): the
// multibody's step is already the blades' multi_rate_step when the deck has `blades`, and the
// scheduler runs one fast group; both in one group is the way to the corrector for the riser.
// The top load is the line's effective tension at the pin (buoyancy as a body force, PIPE.md).
// Waves load the line by Morison on the relative velocity: their kinematics precomputed at its
// undisplaced nodes (as the hydro strips take theirs) and sampled at each small step.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/beam_state.hpp"
#include "fowtsim/beam/solvers.hpp"
#include "fowtsim/core/channels.hpp"
#include "fowtsim/io/schema.hpp"
#include "fowtsim/multibody/loads.hpp"
#include "fowtsim/multibody/model.hpp"
#include "fowtsim/multibody/state.hpp"
#include "fowtsim/waves/precomputed_kinematics.hpp"

namespace fowtsim::driver {

io::Schema riser_schema();

// The hang-off point's motion, in g.
struct HangOffMotion {
  Vec3 position_m = Vec3::Zero();
  Vec3 velocity_m_s = Vec3::Zero();
};

class SeaModules;

class TurbineRiser {
 public:
  // `sea`: the waves' particle kinematics load the line at its undisplaced nodes (none in still water).
  TurbineRiser(const io::ValidatedDeck& deck, const multibody::Model& model, const SeaModules& sea);
  TurbineRiser(const TurbineRiser&) = delete;  // the stepper refers to model_
  TurbineRiser& operator=(const TurbineRiser&) = delete;
  ~TurbineRiser();

  // What changes (a part of the scene state): the line, and its top load averaged over the last
  // large step: [force on the platform at the hang-off point; moment about that point], g [N, N·m].
  struct Data {
    beam::BeamState line;
    Vec6 held = Vec6::Zero();
  };
  // The line at its static equilibrium (gravity, buoyancy, current, internal pressure) with its
  // top at the hang-off point of the platform state `body`, at rest; its top load held.
  Data make_data(const multibody::State& body);

  // The held top load at a Runge–Kutta stage: force at the hang-off point, which turns with the stage's platform.
  void add_stage_loads(const multibody::State& body, const Data& d, multibody::AppliedLoads& out) const;
  // Steps 2–3 of the header: the line over the large step from t to t + dt_large through the hang-off point's motion
  // from `begin` (at its start) to that of `end` (the multibody's state at its end).
  void advance(double t, double dt_large, const HangOffMotion& begin, const multibody::State& end, Data& d);

  HangOffMotion hang_off(const multibody::State& body) const;
  // The line's load on the platform now: [force at the hang-off point; moment about it], g [N, N·m].
  Vec6 top_load(const beam::BeamState& line) const;
  // The anchor's reaction: the load the line puts on the seabed, [force; moment about the anchor], g.
  Vec6 bottom_load(const beam::BeamState& line) const;
  // |M| of the bending moment (about the section's two bending axes) at arclength fraction eta from the anchor [N·m].
  double bending_moment_N_m(const beam::BeamState& line, double eta) const;

  int substeps() const { return substeps_; }
  const beam::BeamModel& line_model() const { return line_; }
  std::vector<ChannelInfo> channels() const;
  void channel_values(const multibody::State& body, const Data& d, std::span<double> out) const;
  std::string description() const;

 private:
  void set_top(const HangOffMotion& top);  // input_ for the top at this motion
  void set_waves(double t);                 // input_'s wave kinematics at time t

  beam::BeamModel line_;  // in g: root at the anchor, tip at the unstretched top
  beam::DynamicOptions options_;
  Vec3 arm_b_m_ = Vec3::Zero();  // hang-off point from the platform reference point, platform frame b [m]
  int substeps_ = 1;
  std::vector<double> gauges_eta_;
  std::unique_ptr<waves::PrecomputedKinematics> waves_;  // at the line's undisplaced nodes; null in still water
  // Workspace of a small step (written before it is read; nothing in it crosses a step).
  std::unique_ptr<beam::DynamicStepper> stepper_;
  beam::BeamInput input_;
};

// Field lists (core/fields.hpp).
template <class Archive>
void fields(Archive& a, TurbineRiser::Data& d) {
  a.io(d.line, d.held);
}

}  // namespace fowtsim::driver
