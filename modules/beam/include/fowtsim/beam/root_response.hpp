#pragma once
// The beam's dynamic stiffness seen at its root: how the root load of one linearised
// generalized-α step of length h responds to the frame's acceleration. For a caller that steps a
// heavier body with the beam's root loads (the multibody under the MBBT blades, DESIGN.md §4), it
// is the beam's apparent mass at the time scale h: the whole rigid mass when the beam's modes are
// fast against h (K h² ≫ M), only the mass near the root when they are slow.
//
// One step from `state` under `input` (the same linearised step DynamicStepper::prepare solves):
//   S Δa = R(0) + s ∂R/∂s,  S = (1−αm) M + (1−αf)γh C + (1−αf)βh² K,
// with ∂R/∂s the inertial load of a unit frame acceleration (frame_acceleration_load), and the
// root load at the balance time affine in Δa (root_residual_load), so its derivative per unit s is
//   ∂F_root/∂s = root_residual_load(w_c + c S⁻¹∂R/∂s, w_k + k S⁻¹∂R/∂s) − root_residual_load(w_c, w_k)
// exactly, for six unit directions at once: one factorisation and six back-substitutions.
#include <array>

#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/beam_state.hpp"
#include "fowtsim/beam/block_tridiagonal.hpp"
#include "fowtsim/beam/solvers.hpp"

namespace fowtsim::beam {

class RootResponse {
 public:
  // Workspace for `model` (sized once; compute() does not allocate).
  RootResponse(const BeamModel& model, double spectral_radius);
  RootResponse(const RootResponse&) = delete;
  RootResponse& operator=(const RootResponse&) = delete;

  // Column j: the root load (force; moment about the root point, both in f: the beam's load on
  // its root, BeamOutputs::root_load's convention) per unit of the frame acceleration
  // [a_f; Ω̇_f] along axis j of f (j < 3: translation [m/s²], j ≥ 3: rotation [rad/s²]) held
  // over a step of h [s] from `state`. A rigid beam gives minus its rigid-body mass matrix about
  // the root. Throws NumericalError if the step matrix is singular.
  Mat6 compute(const BeamInput& input, double h, const BeamState& state);

 private:
  const BeamModel& model_;
  double spectral_radius_;
  BlockTridiagonal matrix_;
  VecX v0_, a0_, w_damping_, w_stiffness_, v_, q_;
  std::array<VecX, 6> per_unit_;
};

}  // namespace fowtsim::beam
