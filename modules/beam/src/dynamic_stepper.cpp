#include <cmath>

#include <fmt/format.h>

#include "erk_integrator.hpp"
#include "fowtsim/beam/solvers.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::beam {

Integrator integrator_from_name(const std::string& name) {
  if (name == "trapezoidal") return Integrator::trapezoidal;
  if (name == "erk") return Integrator::erk;
  throw InputError({"beam", std::nullopt, "integrator", "use trapezoidal or erk"},
                   "unknown beam integrator '" + name + "'");
}

std::string integrator_name(Integrator integrator) {
  return integrator == Integrator::trapezoidal ? "trapezoidal" : "erk";
}

DynamicStepper::DynamicStepper(const BeamModel& model, DynamicOptions options)
    : model_(model), options_(options) {
  const int n = model.node_count();
  system_.resize(n);
  lhs_.resize(n);
  v0_ = VecX::Zero(6 * n);
  q_ = VecX::Zero(6 * n);
  v1_ = VecX::Zero(6 * n);
  work_ = VecX::Zero(6 * n);
  if (options_.integrator == Integrator::erk)
    erk_ = std::make_unique<Erk>(6 * n, options_.erk_relative_tolerance,
                                 options_.erk_absolute_tolerance);
}

DynamicStepper::~DynamicStepper() = default;

void DynamicStepper::step(const BeamInput& input, double dt, BeamState& state) {
  const int n = model_.node_count();
  for (int i = 0; i < n; ++i) v0_.segment<6>(6 * i) = state.velocity[i];
  linearize(model_, input, state, Inertia::included, system_);
  if (options_.integrator == Integrator::trapezoidal)
    integrate_trapezoidal(dt, v0_, q_, v1_);
  else
    integrate_erk(dt, v0_, q_, v1_);

  const double t_end = state.time_s + dt;
  if (!q_.allFinite() || !v1_.allFinite())
    throw NumericalError({"beam", t_end, "increments", "reduce the beam time step"},
                         "non-finite beam increment");
  const double max_rot = update_base(q_, state);
  state.last_increment_rad = max_rot;
  if (max_rot > options_.max_increment_rad)
    throw NumericalError(
        {"beam", t_end, "incremental rotation", "reduce the beam time step dt"},
        fmt::format("an incremental rotation of {:.3g} rad in one step exceeds the small-angle "
                    "limit {:.3g} rad of the piecewise-linear scheme",
                    max_rot, options_.max_increment_rad));
  for (int i = 0; i < n; ++i) state.velocity[i] = v1_.segment<6>(6 * i);
  state.time_s = t_end;
}

// Trapezoidal rule on the first-order form (q0 = 0): with v̄ = (v0 + v1)/2,
//   M (v1 − v0)/Δt + C v̄ + K q1/2 = r,  q1 = Δt v̄
//   ⇒ (2M/Δt + C + Δt/2 K) v̄ = r + 2M v0/Δt.
// A-stable and second order; needs no initial acceleration, so nothing is carried between
// steps but the velocities (eqs. 2.78–2.79).
void DynamicStepper::integrate_trapezoidal(double dt, const VecX& v0, VecX& q, VecX& v) {
  const int n = model_.node_count();
  lhs_ = system_.stiffness;  // same sizes: a copy without allocation
  for (int i = 0; i < n; ++i) {
    lhs_.diag(i) = 0.5 * dt * lhs_.diag(i) + system_.damping.diag(i) + (2.0 / dt) * system_.mass[i];
    if (i + 1 < n) {
      lhs_.upper(i) = 0.5 * dt * lhs_.upper(i) + system_.damping.upper(i);
      lhs_.lower(i) = 0.5 * dt * lhs_.lower(i) + system_.damping.lower(i);
    }
    work_.segment<6>(6 * i) = system_.rhs.segment<6>(6 * i) + (2.0 / dt) * (system_.mass[i] * v0.segment<6>(6 * i));
  }
  if (!lhs_.factor())
    throw NumericalError({"beam", std::nullopt, "step matrix", "check the mass and inertia of the beam"},
                         "singular step matrix (zero mass or inertia?)");
  lhs_.solve_in_place(work_);  // v̄
  q = dt * work_;
  v = 2.0 * work_ - v0;
}

void DynamicStepper::integrate_erk(double dt, const VecX& v0, VecX& q, VecX& v) {
  erk_->integrate(system_, dt, v0, q, v);
  erk_rhs_evaluations_ = erk_->rhs_evaluations();
}

}  // namespace fowtsim::beam
