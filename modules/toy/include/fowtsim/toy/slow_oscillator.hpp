#pragma once
// Toy slow subsystem for verifying the glue code: a heavy mass on a spring to ground, carrying
// an attachment point at its centre. Plays the role of the rigid multibody (platform) in the
// coupled scheme of seed 000 §4.4: advanced at the large step ΔT, loaded by the averaged
// interface loads of the fast subsystem.
//
//   M Ẍ + C Ẋ + K X = F_ifc        (1-D, along g-x)
#include <vector>

#include "fowtsim/core/channels.hpp"
#include "fowtsim/core/interface.hpp"

namespace fowtsim::toy {

struct SlowOscillator {
  struct Params {
    double mass_kg = 1000.0;               // M [kg]
    double stiffness_N_m = 1000.0;         // K [N/m], spring to ground
    double damping_N_s_m = 0.0;            // C [N·s/m], dashpot to ground
    double initial_position_m = 1.0;       // X(0) [m]; released from rest
    double divergence_limit_m = 1e3;       // |X| beyond this is reported as divergence [m]
  };
  struct State {
    double position_m = 0.0;   // X [m], along g-x
    double velocity_m_s = 0.0; // Ẋ [m/s]
  };
  struct Input {
    RootLoads interface_loads;  // loads of the fast subsystem, held constant over the step
  };
  struct Output {
    FrameMotion attachment;     // motion of the attachment point (position, velocity, acceleration)
    double interface_force_N;   // x-component of the applied interface force [N]
  };

  static State make_state(const Params& p);
  // Classical RK4 over [t, t+dt] with the input held (zero-order hold of the averaged load).
  static void advance(const Params& p, const Input& u, double t, double dt, State& s);
  static Output outputs(const Params& p, const Input& u, const State& s);
  static std::vector<ChannelInfo> channels(const Params& p);
};

// Field lists (core/fields.hpp).
template <class Archive>
void fields(Archive& a, SlowOscillator::State& s) {
  a.io(s.position_m, s.velocity_m_s);
}
template <class Archive>
void fields(Archive& a, SlowOscillator::Input& u) {
  a.io(u.interface_loads);
}

}  // namespace fowtsim::toy
