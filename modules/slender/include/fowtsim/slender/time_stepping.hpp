#pragma once
// The time domain as a module the engine steps (DESIGN.md §2; seed 004, slides "Solution in Time
// Domain", solve4XXXTIMEResponse.m and mode_acc.m): the modal first-order system
//   ż = [ȧ; Q_b − C_b ȧ − Ω² a],  z = [a; ȧ]   (the slide's ż = B − Az),
// with C_b = Ψᵀ C Ψ from structural damping only and the full nonlinear Morison force on the
// relative velocity at each strip in Q_b = Ψᵀ Φᵀ (f Δx) (slide "Wave Force - Morison's Equation"):
//   f = ρ Cm A u̇ + ½ρ Cd D |u − v̇|(u − v̇)   (the −ρCaA v̈ part is the added mass in M).
// One `advance` is one classical RK4 step (the seed used ode45) on the wave kinematics the caller
// hands in at t, t + Δt/2 and t + Δt; `outputs` recovers the response at the state's time by mode
// acceleration, q = K⁻¹[Q − MΨä − CΨȧ] with ä = Q_b − C_b ȧ − Ω²a evaluated there, and both bending
// moments (bending_moment.hpp). The _into forms write into a Workspace and an Output sized once
// (make_workspace, make_output): no allocation per step.
#include <vector>

#include <Eigen/Cholesky>

#include "fowtsim/core/channels.hpp"
#include "fowtsim/slender/frequency_domain.hpp"

namespace fowtsim::slender {

struct SlenderBody {
  // Immutable: the model, its modes and the modal matrices of the step.
  struct Params {
    Model model;
    Modes modes;                   // Ψ (n × ζ), ω (ζ)
    MatX strip_modes;              // ΦΨ (N × ζ): strip velocity per modal velocity
    MatX modal_damping;            // C_b = Ψᵀ C Ψ (ζ × ζ) [1/s]
    VecX omega2;                   // Ω² (ζ) [rad²/s²]
    bool mode_acceleration = true; // recover q by mode acceleration (false: q = Ψa; also when ζ = n)
    Eigen::LLT<MatX> stiffness;    // K factorised (n × n), for mode acceleration
  };
  // What the step integrates (plain, copyable: checkpoints, retries).
  struct State {
    long step = 0;   // steps taken from rest: the state is at t = step · Δt
    VecX a;          // modal amplitudes a (ζ) [m·√kg]
    VecX a_dot;      // ȧ (ζ)
  };
  // Wave kinematics at each strip's kinematics point (StripTable::x_kinematics_m) at the step's
  // start t, its midpoint t + Δt/2 and its end t + Δt (columns 0, 1, 2); outputs read column 0.
  struct Input {
    MatX velocity_m_s;        // u (N × 3) [m/s], in the wave direction
    MatX acceleration_m_s2;   // u̇ (N × 3) [m/s²]
  };
  // The response at the state's time.
  struct Output {
    VecX q;                          // generalised coordinates (n)
    VecX displacement_m;             // v at the strip midpoints (N) [m]
    VecX moment_elastic_N_m;         // EI v'' (N) [N·m]
    VecX moment_inertia_relief_N_m;  // inertia-relief moment (N) [N·m]
  };
  // Scratch of advance and outputs: written before it is read, nothing in it crosses a call.
  struct Workspace {
    VecX strip_velocity, relative, force, weighted;  // N
    VecX load, slope, strip_acceleration;            // N
    VecX modal_force, damping_force;                 // ζ
    VecX k1a, k1v, k2a, k2v, k3a, k3v, k4a, k4v;     // RK4 slopes of a and ȧ (ζ)
    VecX stage_a, stage_v, next_a, next_v;           // ζ
    VecX a_ddot, inertial_modal;                     // ζ
    VecX q_modal, generalised_force, mass_force, damping_force_n, inertial_q;  // n
  };

  static State make_state(const Params& params);  // at rest, step 0
  // One RK4 step from t to t + dt; throws NumericalError (with t + dt) and leaves `state` as it was
  // when the new state is not finite.
  static void advance(const Params& params, const Input& input, double t, double dt, State& state, Workspace& work);
  static void advance(const Params& params, const Input& input, double t, double dt, State& state);
  static void outputs(const Params& params, const Input& input, const State& state, Workspace& work, Output& out);
  static Output outputs(const Params& params, const Input& input, const State& state);
  // Per strip i (1-based, bottom to top): Strip<i>Disp [m], Strip<i>MomEI and Strip<i>MomIR [N·m].
  static std::vector<ChannelInfo> channels(const Params& params);
};

// recovery: mode acceleration needs K positive definite (InputError otherwise) and is used only
// when fewer modes than shapes are kept (with all of them it equals q = Ψa).
SlenderBody::Params make_time_domain_params(const Model& model, const Modes& modes, Recovery recovery);
SlenderBody::Input make_input(const SlenderBody::Params& params);      // zero kinematics, sized
SlenderBody::Output make_output(const SlenderBody::Params& params);    // sized
SlenderBody::Workspace make_workspace(const SlenderBody::Params& params);

// Field list (core/fields.hpp).
template <class Archive>
void fields(Archive& a, SlenderBody::State& s) {
  a.io(s.step, s.a, s.a_dot);
}

}  // namespace fowtsim::slender
