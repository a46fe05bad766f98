#include <cmath>

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
  lhs_.resize(n);
  for (VecX* v : {&v0_, &a0_, &q_, &v1_, &a1_, &w_damping_, &w_stiffness_}) *v = VecX::Zero(6 * n);
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
  const int n = model_.node_count();
  for (int i = 0; i < n; ++i) {
    v0_.segment<6>(6 * i) = state.velocity[i];
    a0_.segment<6>(6 * i) = state.acceleration[i];
  }
  if (options_.integrator == Integrator::generalized_alpha)
    integrate_generalized_alpha(input, state, dt);
  else
    integrate_erk(input, state, dt);

  const double t_end = state.time_s + dt;
  if (!q_.allFinite() || !v1_.allFinite())
    throw NumericalError({"beam", t_end, "increments", "reduce the beam time step"},
                         "non-finite beam increment");
  const double max_rot = update_base(q_, state);
  ++matrix_age_;
  turned_since_matrix_ += max_rot;
  if (max_rot > options_.max_increment_rad)
    throw NumericalError(
        {"beam", t_end, "incremental rotation", "reduce the beam time step dt"},
        fmt::format("an incremental rotation of {:.3g} rad in one step exceeds the small-angle "
                    "limit {:.3g} rad of the piecewise-linear scheme",
                    max_rot, options_.max_increment_rad));
  for (int i = 0; i < n; ++i) {
    state.velocity[i] = v1_.segment<6>(6 * i);
    state.acceleration[i] = a1_.segment<6>(6 * i);
  }
  state.acceleration_valid = options_.integrator == Integrator::generalized_alpha;
  state.time_s = t_end;
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
void DynamicStepper::integrate_generalized_alpha(const BeamInput& input, const BeamState& state,
                                                 double dt) {
  const int n = model_.node_count();
  const double rho = options_.spectral_radius;
  const double am = (2.0 * rho - 1.0) / (rho + 1.0), af = rho / (rho + 1.0);
  const double gamma = 0.5 - am + af, beta = 0.25 * (1.0 - am + af) * (1.0 - am + af);

  // Before the first step: the consistent acceleration M a0 = r − C v0 (q0 = 0).
  if (!state.acceleration_valid) {
    linearize(model_, input, state, Inertia::included, system_);
    system_.damping.multiply(v0_, w_damping_);
    for (int i = 0; i < n; ++i)
      a0_.segment<6>(6 * i) = system_.mass[i].partialPivLu().solve(
          Vec6(system_.rhs.segment<6>(6 * i) - w_damping_.segment<6>(6 * i)));
    matrix_valid_ = false;  // a new motion: do not carry a matrix over from another
  }

  w_damping_ = v0_ + ((1.0 - af) * dt) * a0_;
  w_stiffness_ = ((1.0 - af) * dt) * v0_ + (0.5 * (1.0 - af) * dt * dt) * a0_;
  step_residual(model_, input, state, w_damping_, w_stiffness_, a0_, a1_);  // R, solved in place
  const StepWeights weights{1.0 - am, (1.0 - af) * gamma * dt, (1.0 - af) * beta * dt * dt};
  if (step_matrix_is_stale(weights)) {
    assemble_step_matrix(model_, input, state, weights, lhs_);
    if (!lhs_.factor())
      throw NumericalError({"beam", std::nullopt, "step matrix", "check the mass and inertia of the beam"},
                           "singular step matrix (zero mass or inertia?)");
    matrix_valid_ = true;
    matrix_age_ = 0;
    turned_since_matrix_ = 0.0;
    matrix_weights_ = weights;
  }
  lhs_.solve_in_place(a1_);
  a1_ += a0_;
  q_ = dt * v0_ + (dt * dt) * ((0.5 - beta) * a0_ + beta * a1_);
  v1_ = v0_ + dt * ((1.0 - gamma) * a0_ + gamma * a1_);
}

bool DynamicStepper::step_matrix_is_stale(const StepWeights& w) const {
  return !matrix_valid_ || matrix_age_ >= options_.matrix_max_age ||
         turned_since_matrix_ > options_.matrix_max_rotation_rad || w.mass != matrix_weights_.mass ||
         w.damping != matrix_weights_.damping || w.stiffness != matrix_weights_.stiffness;
}

void DynamicStepper::integrate_erk(const BeamInput& input, const BeamState& state, double dt) {
  linearize(model_, input, state, Inertia::included, system_);
  erk_->integrate(system_, dt, v0_, q_, v1_);
  a1_.setZero();
}

}  // namespace fowtsim::beam
