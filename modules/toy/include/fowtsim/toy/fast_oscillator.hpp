#pragma once
// Toy fast subsystem for verifying the glue code: a light, stiff mass on a spring attached to
// the slow body, solved in the floating frame of its attachment point — the 1-D analogue of an
// MBBT blade (seed 000 eq. 2.9: the frame acceleration a_f^W enters as an inertial load).
//
//   m q̈ + c q̇ + k q = −m a_frame(t)     q: position relative to the attachment point
//   load on the carrying body: F_ifc = k q + c q̇ at the attachment point
#include <vector>

#include "fowtsim/core/channels.hpp"
#include "fowtsim/core/interface.hpp"

namespace fowtsim::toy {

struct FastOscillator {
  struct Params {
    double mass_kg = 10.0;                 // m [kg]
    double stiffness_N_m = 4000.0;         // k [N/m], spring to the attachment point
    double damping_N_s_m = 0.0;            // c [N·s/m]
    double initial_position_m = 0.0;       // q(0) [m]; released from rest relative to the frame
    double divergence_limit_m = 1e3;       // |q| beyond this is reported as divergence [m]
  };
  struct State {
    double position_m = 0.0;    // q [m], relative to the attachment point, along g-x
    double velocity_m_s = 0.0;  // q̇ [m/s], relative
  };
  struct Input {
    FrameMotion frame_begin;    // attachment-frame motion at t
    FrameMotion frame_end;      // attachment-frame motion at t + dt (linear in between)
  };
  struct Output {
    RootLoads root_loads;       // load on the carrying body at the attachment point, in g
  };

  static State make_state(const Params& p);
  // Classical RK4 over [t, t+dt], frame acceleration linear between frame_begin and frame_end.
  static void advance(const Params& p, const Input& u, double t, double dt, State& s);
  static Output outputs(const Params& p, const Input& u, const State& s);
  static std::vector<ChannelInfo> channels(const Params& p);
};

// Field lists (core/fields.hpp).
template <class Archive>
void fields(Archive& a, FastOscillator::State& s) {
  a.io(s.position_m, s.velocity_m_s);
}
template <class Archive>
void fields(Archive& a, FastOscillator::Input& u) {
  a.io(u.frame_begin, u.frame_end);
}

}  // namespace fowtsim::toy
