#pragma once
// Equations of motion of the chain, M(q) u̇ = f(q, u, t), by Kane's method (projected
// Newton–Euler): with the Jacobians of kinematics.hpp, for bodies k of mass m_k and inertia I_k
// (about the CM, in g)
//   M = Σ_k m_k J_v,kᵀ J_v,k + J_ω,kᵀ I_k J_ω,k + Pᵀ A P,
//   f = Σ_k J_v,kᵀ (F_k − m_k a_bias,k) + J_ω,kᵀ (M_k − I_k α_bias,k − ω_k × I_k ω_k) + Q_drivetrain,
// where P = [J_v,ref; J_ω,base] maps u to the platform's (a_r, α) and A is the hydrodynamic added
// mass (Kane & Levinson, Dynamics: Theory and Applications, 1985, Ch. 6).
//
// Why this form: its first six rows are exactly the seed's momentum-cloud equations (seed 000
// §1.2.3, ref. [6]): the rate of change of the whole system's linear momentum and of its angular
// momentum about the platform reference point equal the external force and moment, with the
// relative motions of the chain carried by cascading transformation matrices. The momentum cloud
// method prescribes the rotor spin from a separate drivetrain ODE; here the rotor (and generator)
// axial angular-momentum balances are rows 7 (and 8) of the same system, so the spin and the
// platform exchange momentum both ways and a free system conserves energy and angular momentum
// to integration accuracy (tests/conservation_tests.cpp). Exact large angles throughout.
#include "fowtsim/core/types.hpp"
#include "fowtsim/multibody/kinematics.hpp"
#include "fowtsim/multibody/loads.hpp"
#include "fowtsim/multibody/model.hpp"
#include "fowtsim/multibody/state.hpp"

namespace fowtsim::multibody {

using GeneralisedMatrix = Eigen::Matrix<double, kMaxDofs, kMaxDofs>;

// The state at the model's initial conditions (Params::initial_conditions).
State initial_state(const Model& model);

// M(q) (kMaxDofs × kMaxDofs; rows/columns ≥ dof_count are zero) with added mass A about r, g.
GeneralisedMatrix generalised_mass(const Model& model, const State& state, const Mat6& added_mass);

// Everything one evaluation of the equations of motion produces; outputs() reuses it.
struct Evaluation {
  ChainKinematics kinematics;                 // positions, velocities, Jacobians
  GeneralisedVector acceleration = GeneralisedVector::Zero();  // u̇
  GeneralisedMatrix mass = GeneralisedMatrix::Zero();          // M
  GeneralisedVector force = GeneralisedVector::Zero();         // f
  // With AppliedLoads::drivetrain_locked: the generalised torque r on the generator's DOF (LSS side)
  // that keeps it at rest, M u̇ = f + r e_gen with u̇_gen = 0 [N·m]; 0 otherwise.
  double drivetrain_lock_torque_N_m = 0.0;
};

// Solves M u̇ = f for the state under `loads`. Throws NumericalError (module "multibody", time t)
// if M is not positive definite or u̇ is not finite. Allocates nothing.
void evaluate(const Model& model, const State& state, const AppliedLoads& loads, double t,
              Evaluation& out);

// Conserved quantities of the free system, for verification and health monitoring.
struct Invariants {
  double kinetic_energy_J = 0.0;              // Σ ½ m v² + ½ ωᵀ I ω (generator included)
  double potential_energy_J = 0.0;            // drivetrain spring + gravity (if gravity) [J]
  Vec3 linear_momentum_N_s = Vec3::Zero();    // Σ m v, g [N·s]
  Vec3 angular_momentum_N_m_s = Vec3::Zero(); // about the origin of g, g [N·m·s]
};
Invariants invariants(const Model& model, const State& state, bool gravity);

}  // namespace fowtsim::multibody
