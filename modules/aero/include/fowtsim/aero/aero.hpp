#pragma once
// Rotor aerodynamics by steady blade-element momentum theory (bem.hpp) at the blade nodes, with
// tower influence on the inflow (tower_influence.hpp), the Glauert/Pitt–Peters skewed-wake
// redistribution and rotor-level loads and coefficients with OpenFAST AeroDyn channel names.
//
// Frames: g inertial (OpenFAST: X downwind at 0° wind direction, Z up); h hub frame handed in by
// the driver (x_h along the shaft, downwind; rotating with the rotor as OpenFAST's hub frame or
// not — the RtAeroF/M·h channels are resolved in whatever h is given); a airfoil frame of a node
// (below); b node blade frame = a rotated back by θ = twist + pitch about z_a (T_gb = T_ga R_z(θ)).
//
// Airfoil frame a of a node (the node is the aerodynamic centre, the quarter chord):
//   y_a along the chord from the leading to the trailing edge, z_a along the span toward the tip,
//   x_a = y_a × z_a normal to the chord (toward the pressure side in normal operation, downwind).
//   With zero twist and pitch it is the coned blade frame b (OpenFAST blade coordinates).
//
// Unsteady models (Params::unsteady_airfoil, Params::dynamic_inflow; both off by default): their
// per-node states live in State. evaluate() reads them (a const State: the loads at any time within
// a step, e.g. Runge–Kutta stages or output rows, with the states of the step's start) and
// advance_states() integrates them over a step from the evaluation at its end (README "Unsteady
// models"). With both off, or a State not yet started, evaluate() is the quasi-steady BEM.
#include <span>
#include <vector>

#include "fowtsim/aero/bem.hpp"
#include "fowtsim/aero/dynamic_inflow.hpp"
#include "fowtsim/aero/params.hpp"
#include "fowtsim/aero/unsteady_airfoil.hpp"
#include "fowtsim/core/channels.hpp"
#include "fowtsim/core/types.hpp"

namespace fowtsim::aero {

using Points = Eigen::Matrix<double, 3, Eigen::Dynamic>;  // 3 × n vectors, inertial frame g

struct NodeResult {
  SectionSolution section;         // φ, α, a, a', F, W, C_l, C_d, C_m, c_n, c_t, status (after skew)
  double local_radius_m = 0.0;     // distance from the shaft axis [m]
  double axial_velocity_m_s = 0.0;      // V_x along x_b (relative wind incl. tower influence) [m/s]
  double tangential_velocity_m_s = 0.0; // V_y along y_b [m/s]
  double normal_force_N_m = 0.0;   // along x_b, q c c_n (AeroDyn B·N·Fx) [N/m]
  double tangential_force_N_m = 0.0;  // along −y_b (direction of rotation), q c c_t (B·N·Fy) [N/m]
  double theta_rad = 0.0;          // θ = twist + pitch [rad]
  double cos_theta = 1.0;          // cos θ, sin θ of theta_rad (reused while θ stays the same) [-]
  double sin_theta = 0.0;
  // Quasi-steady induced velocities a V_x, a' V_y of the BEM solve (after skew): the input of the
  // dynamic-inflow filters [m/s]. With dynamic inflow off they are those of `section`.
  double quasi_steady_axial_induced_m_s = 0.0;
  double quasi_steady_tangential_induced_m_s = 0.0;
};

struct RotorResult {
  Vec3 force_hub_N = Vec3::Zero();      // aerodynamic force on the rotor in h (RtAeroF·h) [N]
  Vec3 moment_hub_N_m = Vec3::Zero();   // moment about the hub centre in h (RtAeroM·h) [N·m]
  double power_W = 0.0;                 // Ω · M_xh (RtAeroPwr) [W]
  double mean_axial_inflow_m_s = 0.0;   // disk mean of the relative inflow along x_h (RtVAvgxh) [m/s]
  double skew_rad = 0.0;                // angle between the disk-mean inflow and x_h (RtSkew) [rad]
  double radius_m = 0.0;                // largest node distance from the shaft axis [m]
  double area_m2 = 0.0;                 // π radius² (RtArea) [m²]
  double tip_speed_ratio = 0.0;         // Ω R / U (RtTSR) [-]; 0 when |U| < 1e-6 m/s
  double cp = 0.0;                      // P / (½ρ A U³) (RtAeroCp) [-]; same guard
  double ct = 0.0;                      // F_xh / (½ρ A U²) (RtAeroCt) [-]
  double cq = 0.0;                      // M_xh / (½ρ A U² R) (RtAeroCq) [-]
  double mean_quasi_steady_axial_induction = 0.0;  // ā of the BEM solve over converged nodes (Øye's τ1) [-]
};

// Unsteady states of one node (plain data, checkpointed byte for byte).
struct NodeUnsteadyState {
  OyeFilter axial, tangential;            // dynamic inflow filters of a V_x and a' V_y [m/s]
  double quasi_steady_axial_m_s = 0.0;    // W_qs at the state's time (start of the next hold) [m/s]
  double quasi_steady_tangential_m_s = 0.0;
  UnsteadyAirfoilState airfoil;           // HGM states and their inputs at the state's time
};

struct Aero {
  using Params = aero::Params;

  struct State {
    bool started = false;   // false: evaluate() is quasi-steady; advance_states() starts the states
    double time_s = 0.0;    // time of the states [s]
    double tau1_s = 0.0;    // Øye's τ1 at time_s [s]
    std::vector<NodeUnsteadyState> nodes;  // (B·N) when a model is on, else empty
  };

  struct Input {
    Vec3 hub_position_m = Vec3::Zero();    // rotor apex (hub centre) in g [m]
    Mat3 hub_orientation = Mat3::Identity();  // T_gh: columns x_h (shaft, downwind), y_h, z_h [-]
    double rotor_speed_rad_s = 0.0;        // Ω about x_h (OpenFAST sign: + clockwise seen from upwind)
    VecX blade_pitch_rad;                  // (B) pitch of each blade, + toward feather [rad]
    Points node_position_m;                // (3 × B·N) aerodynamic centres in g [m]
    std::vector<Mat3> node_orientation;    // (B·N) T_ga of each node's airfoil frame [-]
    Points node_velocity_m_s;              // (3 × B·N) structural velocity of the nodes in g [m/s]
    Points inflow_velocity_m_s;            // (3 × B·N) undisturbed wind at the nodes in g [m/s]
    VecX node_pitch_rate_rad_s;            // (B·N) section rotation rate about z_a (+ raises α) for the
                                           // unsteady airfoil model; may be left zero [rad/s]
    Vec3 tower_base_position_m = Vec3::Zero();  // tower axis point at elevation 0 in g [m]
    Vec3 tower_axis = Vec3::UnitZ();       // unit vector up the tower axis in g [-]
    double time_s = 0.0;                   // simulation time [s], only for error messages
  };

  struct Output {
    Points force_N_m;                // (3 × B·N) aerodynamic force per unit span at the node, g [N/m]
    Points moment_N_m_m;             // (3 × B·N) pitching moment per unit span about the node, g [N·m/m]
    Points disturbed_inflow_m_s;     // (3 × B·N) inflow with tower influence, g [m/s]
    std::vector<NodeResult> nodes;   // (B·N) section results; their roots warm-start the next evaluate() on this Output
    RotorResult rotor;
    int unconverged_nodes = 0;       // nodes with InductionStatus::no_root (zero induction used)
  };

  // Sized for the models the params ask for (empty when both are off), not started.
  static State make_state(const Params& params);
  // Module contract: evaluates at t + dt into a temporary Output and calls advance_states(). The
  // time loop calls evaluate() + advance_states() on a reused Output instead (no allocation).
  static void advance(const Params& params, const Input& input_at_end, double t, double dt, State& state);
  // Allocates the Output; the time loop should call evaluate() on a reused one.
  static Output outputs(const Params& params, const Input& input, const State& state);
  static std::vector<ChannelInfo> channels(const Params& params);
};

// Field lists (core/fields.hpp): the unsteady states, and an evaluation's input and output
// (checkpointed whole: the node results warm-start the next solve and hold held inductions).
template <class Archive>
void fields(Archive& a, Aero::State& s) {
  a.io(s.started, s.time_s, s.tau1_s, s.nodes);
}
template <class Archive>
void fields(Archive& a, Aero::Input& u) {
  a.io(u.hub_position_m, u.hub_orientation, u.rotor_speed_rad_s, u.blade_pitch_rad, u.node_position_m,
       u.node_orientation, u.node_velocity_m_s, u.inflow_velocity_m_s, u.node_pitch_rate_rad_s,
       u.tower_base_position_m, u.tower_axis, u.time_s);
}
template <class Archive>
void fields(Archive& a, RotorResult& r) {
  a.io(r.force_hub_N, r.moment_hub_N_m, r.power_W, r.mean_axial_inflow_m_s, r.skew_rad, r.radius_m, r.area_m2,
       r.tip_speed_ratio, r.cp, r.ct, r.cq, r.mean_quasi_steady_axial_induction);
}
template <class Archive>
void fields(Archive& a, Aero::Output& y) {
  a.io(y.force_N_m, y.moment_N_m_m, y.disturbed_inflow_m_s, y.nodes, y.rotor, y.unconverged_nodes);
}

// Input and Output sized for params, at rest (identity orientations, zero velocities).
Aero::Input make_input(const Params& params);
Aero::Output make_output(const Params& params);

// How evaluate() finds the inductions: solve the BEM equations at every node, or hold the induced
// velocities (a V_x, a' V_y) the last solve on this Output found and only recompute the loads with
// the current relative velocity — a frozen wake over a short interval (the coupled turbine's small
// steps inside one large step: the induced flow changes on the scale of seconds, the blade
// velocities that aeroelastic damping needs are taken in full at every call). Nodes without a
// converged previous solve are solved.
enum class Induction { solve, held };

// The loads and rotor quantities for the input, into an Output from make_output(). Allocates
// nothing. Throws InputError on a mis-sized input and NumericalError on non-finite data.
void evaluate(const Params& params, const Aero::Input& input, const Aero::State& state,
              Aero::Output& output, Induction induction = Induction::solve);

// True when the params ask for an unsteady model (then the driver advances the states).
inline bool has_unsteady_models(const Params& p) {
  return p.unsteady_airfoil != UnsteadyAirfoilModel::none || p.dynamic_inflow != DynamicInflowModel::none;
}

// τ_p, τ_f and the cutout of params for the unsteady airfoil model.
UnsteadyAirfoilConstants unsteady_airfoil_constants(const Params& params);

// Sets the states to their steady values for the evaluation `at` (an evaluate() of `input` with
// this state) at time t: the filters at the quasi-steady induction, the airfoil states at the
// nodes' α, W and ω. A later evaluate() of the same input then returns the same loads (to round-off).
void start_states(const Params& params, const Aero::Input& input, const Aero::Output& at, double t,
                  Aero::State& state);

// Advances the states from state.time_s to t_end = state.time_s + dt. `at_end` is an evaluate() of
// `input_at_end` (the rotor at t_end) with the state still at its start: it supplies the
// quasi-steady induction and the node kinematics at t_end. The dynamic-inflow filters are solved
// exactly with W_qs linear over the step (τ1 from the mean of the disk's ā, Ū, R at both ends),
// then α, W at t_end are recomputed with the new filtered induction, then the airfoil states are
// advanced (advance_unsteady_airfoil). Starts the states instead if they are not started.
// Allocates nothing.
void advance_states(const Params& params, const Aero::Input& input_at_end, const Aero::Output& at_end, double dt,
                    Aero::State& state);

// Values of channels(params) in the same order; values.size() must equal channels(params).size().
void channel_values(const Params& params, const Aero::Input& input, const Aero::Output& output,
                    std::span<double> values);

}  // namespace fowtsim::aero
