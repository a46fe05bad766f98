#include "fowtsim/beam/root_response.hpp"

#include "fowtsim/beam/linear_system.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::beam {

RootResponse::RootResponse(const BeamModel& model, double spectral_radius)
    : model_(model), spectral_radius_(spectral_radius) {
  const int n = model.node_count();
  matrix_.resize(n);
  for (VecX* v : {&v0_, &a0_, &w_damping_, &w_stiffness_, &v_, &q_}) *v = VecX::Zero(6 * n);
  for (VecX& v : per_unit_) v = VecX::Zero(6 * n);
}

// The trial vectors and weights of DynamicStepper::prepare (dynamic_stepper.cpp) for a step of h.
Mat6 RootResponse::compute(const BeamInput& input, double h, const BeamState& state) {
  if (model_.flow)  // as DynamicStepper::prepare: the pressure's share of the frame-acceleration load is not written
    throw InputError({"beam", std::nullopt, "flow", "a beam without internal flow"},
                     "a pipe's root response to its frame acceleration is not written");
  const int n = model_.node_count();
  for (int i = 0; i < n; ++i) {
    v0_.segment<6>(6 * i) = state.velocity[i];
    a0_.segment<6>(6 * i) = state.acceleration_valid ? state.acceleration[i] : Vec6::Zero();
  }
  const double rho = spectral_radius_;
  const double am = (2.0 * rho - 1.0) / (rho + 1.0), af = rho / (rho + 1.0);
  const double gamma = 0.5 - am + af, beta = 0.25 * (1.0 - am + af) * (1.0 - am + af);
  const StepWeights weights{1.0 - am, (1.0 - af) * gamma * h, (1.0 - af) * beta * h * h};
  w_damping_ = v0_ + ((1.0 - af) * h) * a0_;
  w_stiffness_ = ((1.0 - af) * h) * v0_ + (0.5 * (1.0 - af) * h * h) * a0_;

  assemble_step_matrix(model_, input, state, weights, matrix_);
  if (!matrix_.factor())
    throw NumericalError({"beam", std::nullopt, "root response step matrix", "check the mass and inertia of the beam"},
                         "singular step matrix (zero mass or inertia?)");
  for (int j = 0; j < 6; ++j) {
    const Vec3 unit = Vec3::Unit(j % 3);
    frame_acceleration_load(model_, state, w_stiffness_, j < 3 ? unit : Vec3::Zero(), j < 3 ? Vec3::Zero() : unit,
                            per_unit_[j]);
  }
  for (int j = 0; j < 6; j += 2) matrix_.solve_in_place(per_unit_[j], per_unit_[j + 1]);
  const Vec6 base = root_residual_load(model_, state, w_damping_, w_stiffness_);
  Mat6 response;
  for (int j = 0; j < 6; ++j) {
    v_ = w_damping_ + weights.damping * per_unit_[j];
    q_ = w_stiffness_ + weights.stiffness * per_unit_[j];
    response.col(j) = root_residual_load(model_, state, v_, q_) - base;
  }
  return response;
}

}  // namespace fowtsim::beam
