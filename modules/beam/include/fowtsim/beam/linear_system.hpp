#pragma once
// The locally linear system of one step (seed 000 eq. 2.56), assembled for the whole beam about
// the current base configuration:
//     M q̈ + C q̇ + K q = r,     q = [u*_0; θ*_0; …; u*_{N−1}; θ*_{N−1}] (increments, in f)
//   M  equivalent mass (eq. 2.57), block diagonal
//   C  inertial damping (eq. 2.62: Coriolis, gyroscopic) + structural damping (eq. 2.61)
//   K  elastic stiffness (eq. 2.59, Appendix A) + inertial stiffness (eq. 2.60) + the stiffness of
//      dead loads acting at an arm that rotates with the node
//   r  elastic loads of the base (eqs. 2.63–2.64) + inertial loads of the frame motion
//      (eqs. 2.65–2.66) + external loads
// C and K are block tridiagonal.
//
// Departure from the seed's form: the angular momentum balance of each segment is taken about its
// node (the elastic centre P^n) instead of its mass centre G^n. The physics is the same (the two
// differ by the moment of the segment's linear momentum balance) and the mass matrix becomes
// symmetric, M_n = [m I, −m c̃; m c̃, J_P], with c = G − P and J_P the inertia about P.
// Gravity enters as the frame accelerating at −g, so its eccentric moment m c × g and that
// moment's change with rotation follow from the inertial terms.
#include <vector>

#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/beam_state.hpp"
#include "fowtsim/beam/block_tridiagonal.hpp"
#include "fowtsim/beam/step_matrix.hpp"

namespace fowtsim::beam {

struct LinearizedBeam {
  std::vector<Mat6> mass;       // M, block diagonal
  BlockTridiagonal damping;     // C
  BlockTridiagonal stiffness;   // K
  VecX rhs;                     // r

  void resize(int nodes);
};

enum class Inertia { included, static_only };

// Assemble the system about `state`. With Inertia::static_only, M and the velocity terms of C are
// left zero but the inertial loads and stiffness of a steadily moving frame (centrifugal, gravity)
// stay: the static solver of §2.5 with frame loads.
void linearize(const BeamModel& model, const BeamInput& input, const BeamState& state,
               Inertia inertia, LinearizedBeam& out);

// The matrix of an implicit step, A = m M + c C + k K, assembled in one pass without forming M, C
// and K apart (the section tangents are most of its cost; combined they are built once).
void assemble_step_matrix(const BeamModel& model, const BeamInput& input, const BeamState& state,
                          const StepWeights& weights, BlockTridiagonal& lhs);

// The residual of the locally linear equations at a trial motion, R = r − M a − C w_c − K w_k
// (6 per node), evaluated without forming any matrix: every product is applied as the vector
// formula it stands for, at a fraction of the cost of assembling the matrices.
// A held tip moved by the caller (BeamInput::tip_displacement_m) takes part through `tip`: its
// translation in the stiffness and damping trial vectors (the columns of the held end are not
// unknowns, so its known motion is a load on its neighbour).
struct HeldTipTrial {
  Vec3 stiffness_m = Vec3::Zero();  // the tip's entry of w_k: its displacement from the base [m]
  Vec3 damping_m_s = Vec3::Zero();  // the tip's entry of w_c: its velocity [m/s]
};
void step_residual(const BeamModel& model, const BeamInput& input, const BeamState& state,
                   const VecX& damping_vector, const VecX& stiffness_vector, const VecX& acceleration,
                   VecX& residual, const HeldTipTrial* tip = nullptr);

// ∂R/∂s of step_residual when the frame acceleration grows by s·(da, dω̇) (both in f): the
// inertial loads of that frame acceleration on every node at the trial stiffness vector w_k.
// R is affine in the frame acceleration, so R(s) = R(0) + s·out exactly (the rotor spin solved
// together with the blades, solvers.hpp DynamicStepper::prepare).
void frame_acceleration_load(const BeamModel& model, const BeamState& state, const VecX& stiffness_vector,
                             const Vec3& da, const Vec3& dw_dot, VecX& out);

// The load the root section puts on the root (force; moment about the root point, in f) at a trial
// motion, consistent with step_residual: the root's share of r − C w_c − K w_k. Affine in (w_c, w_k).
// A pipe passes the root face's pressure and momentum flux (root_flow_offset).
Vec6 root_residual_load(const BeamModel& model, const BeamState& state, const VecX& damping_vector,
                        const VecX& stiffness_vector, const Vec6* root_offset = nullptr);

// The section-frame resultant of a pipe's pressure and momentum flux at the root face (none for a
// beam: returns false).
bool root_flow_offset(const BeamModel& model, const BeamInput& input, const BeamState& state, Vec6& out);

// Loads the beam puts on its root (force; moment about the root point), in f, including
// strain-rate damping of the state's velocities.
Vec6 root_reaction(const BeamModel& model, const BeamState& state);

}  // namespace fowtsim::beam
