#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "erk_integrator.hpp"
#include "fowtsim/beam/solvers.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::beam {

Integrator integrator_from_name(const std::string& name) {
  if (name == "generalized_alpha") return Integrator::generalized_alpha;
  if (name == "erk") return Integrator::erk;
  throw InputError({"beam", std::nullopt, "integrator", "use generalized_alpha or erk"},
                   "unknown beam integrator '" + name + "'");
}

std::string integrator_name(Integrator integrator) {
  return integrator == Integrator::generalized_alpha ? "generalized_alpha" : "erk";
}

DynamicStepper::DynamicStepper(const BeamModel& model, DynamicOptions options)
    : model_(model), options_(options) {
  const int n = model.node_count();
  system_.resize(n);
  rebuilt_.resize(n);
  for (VecX* v : {&v0_, &a0_, &q_, &v1_, &a1_, &w_damping_, &w_stiffness_, &solution_, &per_unit_})
    *v = VecX::Zero(6 * n);
  if (options_.integrator == Integrator::erk)
    erk_ = std::make_unique<Erk>(6 * n, options_.erk_relative_tolerance,
                                 options_.erk_absolute_tolerance);
}

DynamicStepper::~DynamicStepper() = default;

double DynamicStepper::input_time_fraction() const {
  if (options_.integrator == Integrator::erk) return 0.5;
  return 1.0 - options_.spectral_radius / (options_.spectral_radius + 1.0);  // 1 − αf
}

void DynamicStepper::step(const BeamInput& input, double dt, BeamState& state) {
  if (options_.integrator == Integrator::generalized_alpha) {
    prepare(input, FrameAccelerationDirection{}, dt, state);
    finish(0.0, state);
    return;
  }
  if (!model_.free_tip() && (input.tip_displacement_m != state.tip_offset_m || !input.tip_velocity_m_s.isZero(0.0)))
    throw InputError({"beam", std::nullopt, "integrator", "generalized_alpha"},
                     "a held tip moved by a prescribed motion needs the generalized_alpha integrator");
  for (int i = 0; i < model_.node_count(); ++i) v0_.segment<6>(6 * i) = state.velocity[i];
  dt_ = dt;
  tip_increment_.setZero();
  integrate_erk(input, state, dt);
  check_increments(state);
  commit(state);
}

// Generalized-α (Chung & Hulbert 1993) on M q̈ + C q̇ + K q = r with q0 = 0 (the base moved to
// the end of the last step):
//   M a_{1−αm} + C v_{1−αf} + K q_{1−αf} = r,  x_{1−α} = (1−α) x1 + α x0,
//   q1 = Δt v0 + Δt² ((½−β) a0 + β a1),  v1 = v0 + Δt ((1−γ) a0 + γ a1),
//   αm = (2ρ∞−1)/(ρ∞+1), αf = ρ∞/(ρ∞+1), γ = ½ − αm + αf, β = ¼ (1 − αm + αf)².
// Written for the change Δa = a1 − a0, one linear solve:
//   [(1−αm) M + (1−αf) γ Δt C + (1−αf) β Δt² K] Δa
//     = r − M a0 − C (v0 + (1−αf) Δt a0) − (1−αf) K (Δt v0 + ½ Δt² a0)   (= R at a1 = a0).
// Velocities and accelerations are resolved in f, so they carry over to the new base unchanged
// (eqs. 2.78–2.79).
AffineRootLoad DynamicStepper::prepare(const BeamInput& input, const FrameAccelerationDirection& direction,
                                       double dt, const BeamState& state) {
  if (options_.integrator != Integrator::generalized_alpha)
    throw InputError({"beam", std::nullopt, "integrator", "generalized_alpha"},
                     "a beam coupled through its frame acceleration needs the generalized_alpha integrator");
  const int n = model_.node_count();
  for (int i = 0; i < n; ++i) {
    v0_.segment<6>(6 * i) = state.velocity[i];
    a0_.segment<6>(6 * i) = state.acceleration[i];
  }
  const double rho = options_.spectral_radius;
  const double am = (2.0 * rho - 1.0) / (rho + 1.0), af = rho / (rho + 1.0);
  gamma_ = 0.5 - am + af;
  beta_ = 0.25 * (1.0 - am + af) * (1.0 - am + af);
  dt_ = dt;

  // Before the first step: the consistent acceleration M a0 = r − C v0 (q0 = 0).
  const bool fresh_motion = !state.acceleration_valid;
  if (fresh_motion) {
    linearize(model_, input, state, Inertia::included, system_);
    system_.damping.multiply(v0_, w_damping_);
    for (int i = 0; i < n; ++i)
      a0_.segment<6>(6 * i) = system_.mass[i].partialPivLu().solve(
          Vec6(system_.rhs.segment<6>(6 * i) - w_damping_.segment<6>(6 * i)));
  }

  w_damping_ = v0_ + ((1.0 - af) * dt) * a0_;
  w_stiffness_ = ((1.0 - af) * dt) * v0_ + (0.5 * (1.0 - af) * dt * dt) * a0_;
  // A held tip moved by the input: its trial motion at the balance time is known, its displacement
  // (1 − αf) q1 = u_tip(t_bal) − u_tip(t) and its velocity u̇_tip(t_bal); it is a load on its neighbour.
  const bool tip_moves = !model_.free_tip() && (input.tip_displacement_m != state.tip_offset_m ||
                                                !input.tip_velocity_m_s.isZero(0.0));
  tip_trial_ = {input.tip_displacement_m - state.tip_offset_m, input.tip_velocity_m_s};
  tip_increment_ = tip_moves ? Vec3(tip_trial_.stiffness_m / (1.0 - af)) : Vec3::Zero();
  step_residual(model_, input, state, w_damping_, w_stiffness_, a0_, solution_,  // R, solved in place
                tip_moves ? &tip_trial_ : nullptr);
  weights_ = {1.0 - am, (1.0 - af) * gamma_ * dt, (1.0 - af) * beta_ * dt * dt};
  // A new motion does not carry a matrix over from another.
  matrix_rebuilt_ = fresh_motion || step_matrix_is_stale(state.step_matrix, weights_);
  if (matrix_rebuilt_) {
    assemble_step_matrix(model_, input, state, weights_, rebuilt_);
    if (!rebuilt_.factor())
      throw NumericalError({"beam", std::nullopt, "step matrix", "check the mass and inertia of the beam"},
                           "singular step matrix (zero mass or inertia?)");
  }
  const BlockTridiagonal& lhs = matrix_rebuilt_ ? rebuilt_ : state.step_matrix.factored;
  Vec6 root_offset_storage;
  const Vec6* root_offset =
      root_flow_offset(model_, input, state, root_offset_storage) ? &root_offset_storage : nullptr;

  // The root load at the balance time is the root section's share of the residual at the trial
  // motion w + (c, k)·Δa (root_residual_load), affine in Δa = solution + s·per_unit.
  const bool coupled = !direction.acceleration_m_s2.isZero(0.0) || !direction.angular_acceleration_rad_s2.isZero(0.0);
  if (coupled && model_.flow)
    throw InputError({"beam", std::nullopt, "flow", "give the pipe's frame acceleration in its input (step())"},
                     "a pipe cannot yet share its frame acceleration with the caller (the pressure's share "
                     "of the frame-acceleration load is not written)");
  AffineRootLoad root;
  if (coupled) {
    frame_acceleration_load(model_, state, w_stiffness_, direction.acceleration_m_s2,
                            direction.angular_acceleration_rad_s2, per_unit_);
    lhs.solve_in_place(solution_, per_unit_);
    // The trial vectors are reused as scratch below and restored by finish() from v0, a0.
    const Vec6 base = root_residual_load(model_, state, w_damping_, w_stiffness_, root_offset);
    v1_ = w_damping_ + weights_.damping * solution_;
    q_ = w_stiffness_ + weights_.stiffness * solution_;
    root.at_zero = root_residual_load(model_, state, v1_, q_, root_offset);
    v1_ = w_damping_ + weights_.damping * per_unit_;
    q_ = w_stiffness_ + weights_.stiffness * per_unit_;
    root.per_unit = root_residual_load(model_, state, v1_, q_, root_offset) - base;
  } else {
    lhs.solve_in_place(solution_);
    per_unit_.setZero();
    v1_ = w_damping_ + weights_.damping * solution_;
    q_ = w_stiffness_ + weights_.stiffness * solution_;
    root.at_zero = root_residual_load(model_, state, v1_, q_, root_offset);
  }
  return root;
}

void DynamicStepper::finish(double s, BeamState& state) {
  solve(s, state);
  commit(state);
}

void DynamicStepper::solve(double s, const BeamState& state) {
  a1_ = a0_ + solution_ + s * per_unit_;
  q_ = dt_ * v0_ + (dt_ * dt_) * ((0.5 - beta_) * a0_ + beta_ * a1_);
  v1_ = v0_ + dt_ * ((1.0 - gamma_) * a0_ + gamma_ * a1_);
  check_increments(state);
}

// Throws if the step's increments are not finite or not small angles; the state stays as it was.
void DynamicStepper::check_increments(const BeamState& state) {
  const int n = model_.node_count();
  const double t_end = state.time_s + dt_;
  if (!q_.allFinite() || !v1_.allFinite())
    throw NumericalError({"beam", t_end, "increments", "reduce the beam time step"},
                         "non-finite beam increment");
  max_rotation_ = 0.0;
  for (int i = 0; i < n; ++i) max_rotation_ = std::max(max_rotation_, q_.segment<3>(6 * i + 3).norm());
  if (max_rotation_ > options_.max_increment_rad)
    throw NumericalError(
        {"beam", t_end, "incremental rotation", "reduce the beam time step dt"},
        fmt::format("an incremental rotation of {:.3g} rad in one step exceeds the small-angle "
                    "limit {:.3g} rad of the piecewise-linear scheme",
                    max_rotation_, options_.max_increment_rad));
}

// Folds the checked increments into the state.
void DynamicStepper::commit(BeamState& state) {
  const int n = model_.node_count();
  StepMatrixCache& cache = state.step_matrix;
  if (options_.integrator == Integrator::generalized_alpha && matrix_rebuilt_) {
    std::swap(cache.factored, rebuilt_);  // O(1): the old matrix becomes the next workspace
    if (rebuilt_.blocks() != n) rebuilt_.resize(n);
    cache.valid = true;
    cache.age = 0;
    cache.turned_rad = 0.0;
    cache.weights = weights_;
  }
  update_base(q_, state);
  state.tip_offset_m += tip_increment_;
  ++cache.age;
  cache.turned_rad += max_rotation_;
  for (int i = 0; i < n; ++i) {
    state.velocity[i] = v1_.segment<6>(6 * i);
    state.acceleration[i] = a1_.segment<6>(6 * i);
  }
  state.acceleration_valid = options_.integrator == Integrator::generalized_alpha;
  state.time_s += dt_;
}

bool DynamicStepper::step_matrix_is_stale(const StepMatrixCache& c, const StepWeights& w) const {
  return !c.valid || c.age >= options_.matrix_max_age || c.turned_rad > options_.matrix_max_rotation_rad ||
         w.mass != c.weights.mass || w.damping != c.weights.damping || w.stiffness != c.weights.stiffness;
}

void DynamicStepper::integrate_erk(const BeamInput& input, const BeamState& state, double dt) {
  linearize(model_, input, state, Inertia::included, system_);
  erk_->integrate(system_, dt, v0_, q_, v1_);
  a1_.setZero();
}

}  // namespace fowtsim::beam
