#pragma once
// The fast side of the coupled turbine (seed 000 §4.4, DESIGN.md §4): three flexible MBBT blades
// and the rotor spin, advanced together at the small step Δt through the motion of the
// non-rotating shaft frame, which the rigid multibody computes at the large step ΔT.
//
// Why the spin is here and not in the multibody. The blades carry ≈ 7× the rotational inertia of
// hub and generator (NREL 5MW: 3.9e7 vs 5.1e6 kg·m²). Handing the blades' root torque to a hub
// whose spin is integrated apart is an added-mass partition, unstable above ΔT ≈ 2 ms whatever n
// (measured, DESIGN.md §4). So in every small step the hub spin acceleration is one more unknown
// of the blades' linear systems: each blade's generalized-α step is affine in it
// (beam::DynamicStepper::prepare), the hub and drivetrain balance about the shaft closes the
// system (one or two scalars bordering three block-tridiagonal systems: O(N)), and then the
// blades finish their steps with the solved value. The multibody takes azimuth, speed and
// acceleration as prescribed (multibody::RotorSpin::prescribed).
//
// Frames (multibody/model.hpp): s shaft (non-rotating), h = s R_x(ψ) hub, r_i blade-i root frame
// (coned), f_i = r_i R_z(−β_i) the pitched root frame in which blade i is a cantilever (BeamDyn's
// blade frame: the blade table's twist is relative to it; positive pitch β toward feather, as
// the aero module's airfoil frame T_ga = T_gb R_z(−(twist + β))).
#include <array>
#include <memory>
#include <vector>

#include "coupling/multi_rate_scheduler.hpp"
#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/beam_outputs.hpp"
#include "fowtsim/beam/beam_state.hpp"
#include "fowtsim/beam/root_response.hpp"
#include "fowtsim/beam/solvers.hpp"
#include "fowtsim/multibody/kinematics.hpp"
#include "fowtsim/multibody/model.hpp"
#include "rotor/rotor_aero.hpp"

namespace fowtsim::driver {

class BladeAeroMap;

inline constexpr int kBlades = 3;

// Motion of the shaft frame s at the rotor apex, all in g: what the multibody hands the fast side.
struct ShaftMotion {
  Vec3 apex_position_m = Vec3::Zero();
  Vec3 apex_velocity_m_s = Vec3::Zero();
  Vec3 apex_acceleration_m_s2 = Vec3::Zero();
  Mat3 orientation = Mat3::Identity();               // T_gs
  Vec3 angular_velocity_rad_s = Vec3::Zero();        // ω_s in g
  Vec3 angular_acceleration_rad_s2 = Vec3::Zero();   // α_s in g
  Vec3 tower_base_m = Vec3::Zero();                  // tower-axis point at SWL elevation (aero tower influence)
  Vec3 tower_axis = Vec3::UnitZ();
};
ShaftMotion shaft_motion(const multibody::ChainKinematics& chain, const multibody::GeneralisedVector& udot);
// Vectors linearly, orientation along the geodesic: the slow motion inside a large step.
ShaftMotion interpolate(const ShaftMotion& a, const ShaftMotion& b, double x);

// Motion of one pitched blade-root frame f_i, in g.
struct BladeFrame {
  Mat3 orientation = Mat3::Identity();               // T_gf
  Vec3 root_m = Vec3::Zero();                        // root point
  Vec3 root_velocity_m_s = Vec3::Zero();
  Vec3 root_acceleration_m_s2 = Vec3::Zero();
  Vec3 angular_velocity_rad_s = Vec3::Zero();
  Vec3 angular_acceleration_rad_s2 = Vec3::Zero();
  Vec3 arm_m = Vec3::Zero();                         // root − apex
};

enum class SpinMode { free, held };

struct FlexibleRotorParams {
  beam::BeamModel blade;                 // one blade, clamped at the origin of f
  beam::DynamicOptions dynamics;         // generalized-α (ρ∞, matrix reuse)
  double hub_inertia_kg_m2 = 0.0;        // HubIner about the shaft
  double hub_mass_kg = 0.0;              // HubMass (for the shaft's thrust channel)
  double hub_cm_m = 0.0;                 // HubCM: apex to the hub's CM along the shaft, + downwind [m]
  double generator_inertia_kg_m2 = 0.0;  // GenIner about the HSS
  double gearbox_ratio = 1.0;
  bool torsional_flexibility = false;
  double torsional_stiffness_N_m_rad = 0.0, torsional_damping_N_m_s_rad = 0.0;
  SpinMode spin = SpinMode::free;
  std::array<Mat3, kBlades> root_orientation_h{};  // T_h,r_i
  std::array<Vec3, kBlades> root_h{};              // root point in h from the apex [m]
  double gravity_m_s2 = 9.80665;
  // Blade pitch actuator: β̈ = ω² (β_cmd − β) − 2ζω β̇, so a demand held over ΔT does not step
  // the pitch (and the blades' frame) every large step.
  double pitch_natural_frequency_rad_s = 2.0 * 3.141592653589793 * 2.0;
  double pitch_damping_ratio = 0.7;
  // BEM inductions solved at every small step, or at the first small step of each large step
  // and held over the others (aero::Induction::held: loads still follow the blade motion).
  bool induction_every_small_step = false;
};

// Spin of rotor (ψ) and generator (θ_g, LSS-equivalent) as generalized-α variables: the
// accelerations are the algorithm's, the physical one is the mean over the last small step.
struct SpinState {
  double rotor_azimuth_rad = 0.0, rotor_speed_rad_s = 0.0, rotor_acceleration_rad_s2 = 0.0;
  double generator_azimuth_rad = 0.0, generator_speed_rad_s = 0.0, generator_acceleration_rad_s2 = 0.0;
  double rotor_mean_acceleration_rad_s2 = 0.0;      // (ψ̇1 − ψ̇0)/Δt of the last small step
  double generator_mean_acceleration_rad_s2 = 0.0;
  // With RotorDemands::drivetrain_locked: the torque the lock took in the last small step's balance,
  // on the generator (LSS side; the rotor's with a rigid shaft) [N·m]; 0 otherwise.
  double lock_torque_N_m = 0.0;
};

// Everything the fast side integrates: plain, copyable (a copy continues bit-identically: each
// beam state carries its factored step matrix).
struct FlexibleRotorState {
  std::array<beam::BeamState, kBlades> blades;
  SpinState spin;
  std::array<double, kBlades> pitch_rad{}, pitch_rate_rad_s{}, pitch_acceleration_rad_s2{};
  double time_s = 0.0;
};

// What the slow side holds over a large step.
struct RotorDemands {
  double generator_torque_N_m = 0.0;   // HSS
  std::array<double, 3> pitch_command_rad{};  // per blade [rad]
  bool drivetrain_locked = false;              // an HSS brake holds the generator (a rigid shaft: the rotor) at rest
  bool gravity = true;
};

class FlexibleRotor {
 public:
  // `aero` and `map` may be null (no aerodynamics); they must outlive the rotor.
  FlexibleRotor(FlexibleRotorParams params, const RotorAero* aero, const BladeAeroMap* map);
  FlexibleRotor(const FlexibleRotor&) = delete;  // the steppers refer to params_.blade
  FlexibleRotor& operator=(const FlexibleRotor&) = delete;

  // The blades' root loads on the hub, as a force at the apex and a moment about it, in the hub
  // frame h (kept in h so that the slow side turns them with the hub at every stage instead of
  // letting them lag by Ω·ΔT). The scheduler averages them over a large step.
  struct HubLoad {
    Vec3 force_h_N = Vec3::Zero();
    Vec3 moment_h_N_m = Vec3::Zero();
    HubLoad& operator+=(const HubLoad& b) {
      force_h_N += b.force_h_N;
      moment_h_N_m += b.moment_h_N_m;
      return *this;
    }
    friend HubLoad operator*(double w, const HubLoad& a) { return {w * a.force_h_N, w * a.moment_h_N_m}; }
  };
  // What changes (a part of the scene state): the blades, spin and pitch, and the shaft motion and
  // root loads at state.time_s (the first sample of the next large step).
  struct Data {
    FlexibleRotorState state;
    ShaftMotion shaft;
    HubLoad last;
  };
  Data make_data() const;  // undeformed blades at rest; start() sets them up

  // How the blades start, moving rigidly with their root frames: at their static solution under
  // the frame motion, gravity and (if any) aerodynamics at t = 0; at the static solution under
  // the frame motion alone (BeamDyn's QuasiStaticInit, as OpenFAST starts); or undeformed.
  // `aero` is the rotor aerodynamics' data (null without aerodynamics).
  enum class Start { static_loads, centrifugal, undeformed };
  void start(const ShaftMotion& shaft, double azimuth_rad, double rotor_speed_rad_s, double pitch_rad,
             const RotorDemands& demands, Start how, Data& d, RotorAero::Data* aero);

  // One small step from t to t + dt (small step `slow.i` of `slow.n`) through the shaft motion
  // interpolated over the large step (coupling/multi_rate_scheduler.hpp). The inductions are
  // solved at its first small step, or at every one (FlexibleRotorParams).
  void advance(double t, double dt, const SubstepMotion<ShaftMotion>& slow, const RotorDemands& demands, Data& d,
               RotorAero::Data* aero);

  // The rotor's apparent mass on the shaft over a step of h (the interface Jacobian of the staggered
  // exchange, scenes/turbine_blades.hpp): M with the three blades' root load on the hub
  // ≈ F_0 − M [a_apex; α_s] (force at the apex and moment about it; the apex's and the
  // non-rotating shaft's accelerations; all in h), the spin free as this side solves it.
  //  * Blades, the hub's spin held: from each blade's linearised generalized-α step of h from
  //    `state` (beam::RootResponse, P_b per unit of its root frame's acceleration) with the root
  //    frame's rigid-body map X_b (h → f):
  //      M_b = −Σ_b X_bᵀ P_b X_b,  X_b = [T_fh  −T_fh [ρ_b]×; 0  T_fh],  ρ_b the root from the apex in h;
  //  * the spin condensed out: the hub turns at α = α_s + ψ̈ e, and ψ̈ (with θ̈ of the generator) is
  //    what the balances of step() give for a shaft acceleration y = [a_apex; α_s] — per unit of
  //    physical acceleration, with the shaft spring and damper as the step's κ = (1−αf)(kβh² + cγh)/(1−αm):
  //      K [ψ̈; θ̈] = −B y,  K = [J_h + M_ee + κ   −κ; −κ   N²J_g + κ],  B = [M_e·+ J_h eᵀ; N J_g eᵀ]
  //    (rigid shaft ψ̈ = θ̈: the two rows summed; a brake holding the generator: θ̈ = 0). The blades'
  //    load changes by −M_b e ψ̈, and the hub's and generator's inertia, which the multibody takes at
  //    the prescribed ψ̈, θ̈ of the last step, by −(J_h ψ̈ + N J_g θ̈) e about the shaft, so
  //      M = M_b − Bᵀ K⁻¹ B,
  //    the Schur complement: a free rotor lends the shaft only the part of its spin inertia the
  //    generator drags along (without it, the tower's second side-side mode, which turns the top
  //    about the shaft at 4.2 Hz, would be loaded with the blades' whole spin inertia and lag it).
  // Returned symmetrised (the gyroscopic part of the blades' step, small, stays in the explicit
  // remainder; the multibody's Cholesky needs a symmetric mass).
  // The blades' node loads are left out of the linearisation (their follower arm adds a stiffness
  // of the aero load's order, not an inertia): what is left out is exchanged with the remainder.
  Mat6 apparent_mass_h(const ShaftMotion& shaft, const FlexibleRotorState& state, double h, const RotorDemands& demands);
  // Its two parts, so that a blade's share is refreshed alone: blade b's −X_bᵀ P_b X_b, and the sum of
  // the blades' with the spin condensed out.
  Mat6 blade_apparent_mass_h(const ShaftMotion& shaft, const FlexibleRotorState& state, double h, int blade, bool gravity);
  Mat6 with_spin_condensed(const Mat6& blades, double h, const RotorDemands& demands) const;
  // The step h that stands for a large step of dt_large in n small steps: the blades see a shaft
  // acceleration that changes at the step's start, and what the multibody gets is their load over
  // the step, so a mode of frequency ω takes up ω² ⟨t²⟩/2 of it to leading order, ⟨t²⟩ = ΔT² (1/3 +
  // 1/(6n²)) with the scheduler's trapezoidal weights; one generalized-α step of h takes up
  // (w_k/w_m) ω² h² (w: the step matrix's weights). Equal for
  //   h = ΔT √((1/3 + 1/(6n²)) w_m / (2 w_k))     (ρ∞ = 0, n = 4: 0.586 ΔT).
  // Measured against finite differences of the blades' large step (interface_mass_tests.cpp): the
  // diagonal within 12 %; h = ΔT makes the real blades' tilt and yaw inertia 1.9× too heavy.
  double apparent_mass_step(double dt_large, int n) const;

  const FlexibleRotorParams& params() const { return params_; }
  // Motion of blade i's pitched root frame for the shaft motion and the spin and pitch of `state`.
  BladeFrame frame(const ShaftMotion& shaft, int blade, const FlexibleRotorState& state) const;
  beam::BeamOutputs blade_outputs(int blade, const FlexibleRotorState& state) const {
    return beam::beam_outputs(params_.blade, state.blades[blade]);
  }

 private:
  void evaluate_aero(double t, const ShaftMotion& shaft, bool solve_induction, Data& d, RotorAero::Data* aero);
  void step(double t, double dt, const ShaftMotion& shaft, const RotorDemands& demands, bool solve_induction, Data& d,
            RotorAero::Data* aero);
  void advance_pitch(double dt, const std::array<double, 3>& command, FlexibleRotorState& state) const;
  HubLoad root_loads(const ShaftMotion& shaft, const FlexibleRotorState& state) const;

  FlexibleRotorParams params_;
  const RotorAero* aero_;
  const BladeAeroMap* map_;
  // Workspace of a small step (written before it is read; nothing in it crosses a step).
  std::array<std::unique_ptr<beam::DynamicStepper>, kBlades> steppers_;
  std::array<beam::BeamInput, kBlades> inputs_;
  std::array<std::vector<Vec6>, kBlades> aero_loads_;
  std::unique_ptr<beam::RootResponse> response_;  // workspace of apparent_mass_h
  beam::BeamInput response_input_;
};

// Field lists (core/fields.hpp).
template <class Archive>
void fields(Archive& a, FlexibleRotorState& s) {
  a.io(s.blades, s.spin, s.pitch_rad, s.pitch_rate_rad_s, s.pitch_acceleration_rad_s2, s.time_s);
}
template <class Archive>
void fields(Archive& a, ShaftMotion& m) {
  a.io(m.apex_position_m, m.apex_velocity_m_s, m.apex_acceleration_m_s2, m.orientation, m.angular_velocity_rad_s,
       m.angular_acceleration_rad_s2, m.tower_base_m, m.tower_axis);
}
template <class Archive>
void fields(Archive& a, FlexibleRotor::HubLoad& h) {
  a.io(h.force_h_N, h.moment_h_N_m);
}
template <class Archive>
void fields(Archive& a, FlexibleRotor::Data& d) {
  a.io(d.state, d.shaft, d.last);
}

}  // namespace fowtsim::driver
