#pragma once
// What the beam integrates (State) and what the driver hands in each step (Input).
//
// The unknowns are the base configuration of every node — position x_n and orientation R_n in
// the floating frame f — and the node velocities relative to f. Each step solves for small
// increments (u*_n, θ*_n) about this base (seed 000 eqs. 2.42–2.43) and folds them into it
// (eqs. 2.67–2.68) with exact rotations. Increments and velocities are resolved in f, so the
// velocity transfer to the new base (eqs. 2.78–2.79, which rotate q-frame components) is the
// identity here.
#include <vector>

#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/step_matrix.hpp"
#include "fowtsim/core/types.hpp"

namespace fowtsim::beam {

// Motion of the floating frame f the beam root is clamped to, all components in f.
struct FrameKinematics {
  Vec3 acceleration_m_s2 = Vec3::Zero();          // a_f^W: acceleration of f's origin [m/s²]
  Vec3 angular_velocity_rad_s = Vec3::Zero();     // Ω_f [rad/s]
  Vec3 angular_acceleration_rad_s2 = Vec3::Zero();  // Ω̇_f [rad/s²]
  Vec3 gravity_m_s2 = Vec3::Zero();               // g resolved in f [m/s²]
};

// Dead loads (fixed direction in f) for one step.
struct BeamInput {
  FrameKinematics frame;
  std::vector<Vec6> node_loads;  // [force N; moment N·m] on segment n, acting at its load arm
                                 // (empty = none); distributed loads integrated over the segment
  Vec6 tip_load = Vec6::Zero();  // [force; moment] at the tip point [N, N·m]
  // Prescribed motion of a held (clamped or pinned) tip at the input time: its translation from the
  // undeformed tip point and its velocity, in f [m, m/s] (seed 000 eqs. 3.66–3.67: a riser's top
  // moved by the platform). Its orientation stays. A free tip ignores them; generalized_alpha only.
  Vec3 tip_displacement_m = Vec3::Zero();
  Vec3 tip_velocity_m_s = Vec3::Zero();
  // The sea's wave particle velocity and local acceleration at each node, in f [m/s, m/s²] (empty:
  // still water): with BeamModel::water, added to its current in the drag's relative velocity and
  // loading the wet volumes by Morison's inertia term C_m ρ A_e Δs (I − t tᵀ) a_w.
  std::vector<Vec3> water_velocity_m_s;
  std::vector<Vec3> water_acceleration_m_s2;
};

struct BeamState {
  double time_s = 0.0;
  std::vector<Vec3> position_m;   // x_n: base position of node n, in f [m]
  std::vector<Mat3> orientation;  // R_n: local frame of node n (columns in f)
  std::vector<Vec6> velocity;     // [ẋ_n; ω_n] relative to f, in f [m/s; rad/s]
  std::vector<Vec6> acceleration;  // generalized-α's algorithmic acceleration, in f [m/s²; rad/s²]
  bool acceleration_valid = false;  // false: solved from M a = r − C v before the first step
  StepMatrixCache step_matrix;      // generalized-α's factored step matrix, reused while fresh
  Vec3 tip_offset_m = Vec3::Zero();  // a held tip's translation from its undeformed point, in f [m]: part of
                                     // the base configuration, advanced by each step to the prescribed motion
};

// Its field list (core/fields.hpp): a checkpoint or a copy continues bit-identically only with
// the factored step matrix.
template <class Archive>
void fields(Archive& a, BeamState& s) {
  a.io(s.time_s, s.position_m, s.orientation, s.velocity, s.acceleration, s.acceleration_valid, s.step_matrix,
       s.tip_offset_m);
}

// Undeformed, at rest relative to f.
BeamState make_state(const BeamModel& model);

}  // namespace fowtsim::beam
