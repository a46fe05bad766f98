#pragma once
// The two solvers of seed 000 §2.5 on the piecewise-linear system of linear_system.hpp:
//  * static: repeated linear solves K q = r, each folded into the base (§2.4.3), until the
//    increments vanish — Newton's method, since K is the exact tangent of the discrete loads;
//  * dynamic: one linear solve per step about the base of the previous step, no iteration
//    (§2.4.3), with either integrator of the locally linear system:
//      - generalized_alpha: Chung–Hulbert generalized-α, A-stable and second order with
//        high-frequency dissipation set by the spectral radius ρ∞ (ρ∞ = 1: average acceleration,
//        no dissipation); one block-tridiagonal solve per step against a factorised step matrix
//        that is rebuilt when it grows stale (DynamicOptions::matrix_max_*);
//      - erk: SUNDIALS ARKODE explicit Dormand–Prince 5(4) with adaptive internal steps, the
//        seed's ode45 setting (relative tolerance 1e-6) — the reference.
#include <memory>
#include <string>

#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/beam_state.hpp"
#include "fowtsim/beam/linear_system.hpp"

namespace fowtsim::beam {

struct StaticOptions {
  int load_steps = 1;             // loads applied in equal fractions, equilibrium at each
  int max_iterations = 100;       // per load step
  double tolerance = 1e-10;       // RMS increment, translations / beam length and rotations [-]
  double max_rotation_rad = 0.5;  // an iterate turning a node more than this is scaled down
};

struct StaticReport {
  int iterations = 0;       // total over all load steps
  double final_increment = 0.0;
};

// Static equilibrium under `input` (dead loads, gravity, steady frame motion, a held tip moved to
// input.tip_displacement_m); throws NumericalError if an iteration fails or does not converge.
StaticReport solve_static(const BeamModel& model, const BeamInput& input, BeamState& state,
                          const StaticOptions& options = {});

enum class Integrator { generalized_alpha, erk };
Integrator integrator_from_name(const std::string& name);  // "generalized_alpha" | "erk"
std::string integrator_name(Integrator integrator);

struct DynamicOptions {
  Integrator integrator = Integrator::generalized_alpha;
  // ρ∞ of generalized-α. The piecewise-linear update is not energy-conserving for modes the step
  // does not resolve (a stiff tip segment flips about its equilibrium every step and the exact
  // rotation update turns that into growth), so some dissipation is needed; BeamDyn's decks use 0.
  double spectral_radius = 0.0;
  // Largest incremental rotation allowed in one step. The linearisation drops terms of relative
  // size |θ*|/2 (sin θ ≈ θ, cos θ ≈ 1 − θ²/2 → 1); 0.1 rad keeps them below 5 %, beyond which the
  // step is no longer a small-angle increment (seed §2.4: "when the incremental rotation within
  // each time-step conforms to small-angle assumptions").
  double max_increment_rad = 0.1;
  // Reuse of generalized-α's factored step matrix A = (1−αm) M + (1−αf)γΔt C + (1−αf)βΔt² K.
  // Every step solves A Δa = R for the change of acceleration, with R the residual of the
  // locally linear equations (eq. 2.56) at the current base, evaluated exactly and cheaply
  // without matrices (step_residual). A only steers that correction, so an A from a nearby base
  // changes the result by (A_old⁻¹ A − I) Δa, second order in the step (a modified-Newton or
  // W-method step; CVODE likewise keeps its Newton matrix for up to 20 steps). max_age = 1
  // rebuilds it every step: the seed's scheme, to rounding. A is rebuilt when any limit is
  // reached, or when Δt changes. The defaults keep the change below 1 % of the time-discretisation
  // error (halving Δt) on the rotating benchmarks of seeds 000 §2.5.3 and 002 §5.2, where A
  // changes most (matrix_reuse_tests.cpp):
  int matrix_max_age = 20;                  // steps since it was built
  double matrix_max_rotation_rad = 0.002;   // Σ over steps of the largest node rotation since:
                                            // A's stiff axial and shear directions turn with the
                                            // sections and must not leak into the soft bending ones
  double erk_relative_tolerance = 1e-6;   // seed §2.5: ode45 RelTol
  double erk_absolute_tolerance = 1e-12;  // on increments [m, rad] and their rates
};

// Frame acceleration per unit of a scalar s the caller solves for (DynamicStepper::prepare), in f.
struct FrameAccelerationDirection {
  Vec3 acceleration_m_s2 = Vec3::Zero();           // ∂a_f/∂s
  Vec3 angular_acceleration_rad_s2 = Vec3::Zero();  // ∂Ω̇_f/∂s
};

// The root load (force; moment about the root point, in f) at the step's balance time
// t + (1 − αf)Δt as the affine function at_zero + s·per_unit of the frame-acceleration scalar s.
struct AffineRootLoad {
  Vec6 at_zero = Vec6::Zero();
  Vec6 per_unit = Vec6::Zero();
};

// Workspace of the dynamic step: sized on first use, reused without allocation afterwards. The
// factored step matrix it reuses lives in BeamState::step_matrix.
class DynamicStepper {
 public:
  DynamicStepper(const BeamModel& model, DynamicOptions options);
  ~DynamicStepper();
  DynamicStepper(const DynamicStepper&) = delete;
  DynamicStepper& operator=(const DynamicStepper&) = delete;

  // Advance state by dt under `input`, evaluated at t + input_time_fraction()·dt. Throws
  // NumericalError on a non-finite result, a singular system or an increment above
  // max_increment_rad, and then leaves `state` as it was (a caller may retry with a smaller dt).
  void step(const BeamInput& input, double dt, BeamState& state);

  // The same step in two halves, for a frame acceleration that is partly unknown: the input's
  // plus s·direction, where the caller solves for s from the root load this step returns (the
  // rotor spin solved together with the blades, DESIGN.md §4). The residual is affine in s
  // (frame_acceleration_load), so the step's solution is Δa(s) = A⁻¹R(0) + s A⁻¹ ∂R/∂s: one
  // extra block-tridiagonal solve. prepare() does not touch `state`; finish(s, state) must get
  // the same state and completes the step exactly as step() would with that frame acceleration.
  // finish = solve(s), which computes and checks the increments (throwing before any state is
  // touched), then commit(state): several beams sharing s can all be checked before any moves.
  // generalized_alpha only.
  AffineRootLoad prepare(const BeamInput& input, const FrameAccelerationDirection& direction, double dt,
                         const BeamState& state);
  void finish(double s, BeamState& state);
  void solve(double s, const BeamState& state);
  void commit(BeamState& state);

  // Where in the step the input must be sampled to keep second order: generalized-α balances
  // forces at t + (1 − αf) Δt (= t + Δt for ρ∞ = 0); the erk integrator holds the input constant
  // over the step, best taken at the middle.
  double input_time_fraction() const;
  const DynamicOptions& options() const { return options_; }

  struct Erk;  // ARKODE state of the erk integrator (src/erk_integrator.hpp)

 private:
  bool step_matrix_is_stale(const StepMatrixCache& cache, const StepWeights& weights) const;
  void check_increments(const BeamState& state);
  void integrate_erk(const BeamInput& input, const BeamState& state, double dt);

  const BeamModel& model_;
  DynamicOptions options_;
  LinearizedBeam system_;
  BlockTridiagonal rebuilt_;   // a fresh step matrix, moved into the state when the step succeeds
  bool matrix_rebuilt_ = false;
  StepWeights weights_;
  double dt_ = 0.0;
  double beta_ = 0.25, gamma_ = 0.5;
  double max_rotation_ = 0.0;  // of the checked increments
  VecX v0_, a0_, q_, v1_, a1_, w_damping_, w_stiffness_, solution_, per_unit_;
  HeldTipTrial tip_trial_;                // a held tip moved by the input (BeamInput::tip_displacement_m)
  Vec3 tip_increment_ = Vec3::Zero();     // its translation over the step, folded into BeamState::tip_offset_m
  std::unique_ptr<Erk> erk_;
};

// Fold increments q (u*, θ* per node, in f) into the base: x ← x + u*, R ← exp(θ̃*) R
// (eqs. 2.67–2.68 with the exact exponential instead of I + θ̃*). Returns max |θ*|.
double update_base(const VecX& q, BeamState& state);

}  // namespace fowtsim::beam
