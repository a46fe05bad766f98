#pragma once
// Quasi-static mooring of one floating platform (DESIGN.md §2 module contract): every line is in
// static equilibrium with the instantaneous fairlead position, either as a massless taut spring
// (seed 000 §4.4/§4.5.1) or as an elastic catenary with seabed contact and friction (MAP/FAST,
// Jonkman 2007 §4.2). Loads on the platform are summed about its reference point.
//
// Frames (DESIGN.md §3): g = inertial (origin at SWL on the undisplaced centre line, z up);
// b = platform body frame, origin at the platform reference point. Line i's fairlead is at
// p_F = p_ref + T_gb r_b,i; its anchor p_A is fixed in g.
#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "fowtsim/core/channels.hpp"
#include "fowtsim/core/interface.hpp"
#include "fowtsim/core/types.hpp"
#include "fowtsim/mooring/catenary.hpp"
#include "fowtsim/mooring/params.hpp"

namespace fowtsim::mooring {

// Per-line results at one pose.
struct LineOutput {
  double fairlead_tension_N = 0.0;  // |tension| at the fairlead [N] (channel FAIRTENi)
  double anchor_tension_N = 0.0;    // |tension| at the anchor [N] (channel ANCHTENi)
  double fairlead_h_N = 0.0;        // H: horizontal tension at the fairlead [N] (FAIRHi); taut: horizontal part
  double fairlead_v_N = 0.0;        // V: vertical tension at the fairlead, > 0 pulling down [N] (FAIRVi)
  double anchor_h_N = 0.0;          // horizontal tension at the anchor [N]
  double anchor_v_N = 0.0;          // vertical tension at the anchor, > 0 pulling the anchor up [N]
  double grounded_length_m = 0.0;   // unstretched length resting on the seabed [m] (catenary)
  Vec3 fairlead_m = Vec3::Zero();   // fairlead position, g [m]
  Vec3 force_N = Vec3::Zero();      // force of the line on the platform at the fairlead, g [N]
  CatenaryRegime regime = CatenaryRegime::suspended;  // catenary branch (taut: suspended)
  bool slack = false;               // taut spring shorter than its unstretched length (no tension)
  int iterations = 0;               // solver iterations spent on this line
};

struct QuasiStaticMooring {
  using Params = MooringParams;

  struct Input {
    FrameMotion platform;           // pose of the platform reference point: position_m in g, orientation T_gb
    std::optional<double> time_s;   // simulation time of this pose [s]; only to date error messages
  };

  // Warm start of one line: the last converged fairlead tensions.
  struct LineWarmStart {
    double h_N = 0.0;    // H [N]
    double v_N = 0.0;    // V [N]
    bool valid = false;  // false until a solution exists (cold start from the Peyrot–Goulois guess)
  };
  // Quasi-static lines have no dynamics: the state is only the solver's warm start. Fixed size,
  // trivially copyable.
  struct State {
    std::array<LineWarmStart, kMaxLines> lines{};  // entry i for line i; the rest unused
  };

  struct Output {
    Vec3 force_N = Vec3::Zero();     // total mooring force on the platform, g [N]
    Vec3 moment_N_m = Vec3::Zero();  // total moment about the reference point, g [N·m] (incl. the yaw spring)
    double yaw_spring_moment_N_m = 0.0;  // z-moment of the delta-connection yaw spring [N·m] (in moment_N_m)
    std::size_t line_count = 0;      // lines in use
    std::array<LineOutput, kMaxLines> lines{};  // entry i for line i
  };

  // Validates the parameters (InputError) and returns a cold state.
  static State make_state(const Params& p);

  // Solves every line at the pose in `u` (the pose at the end of the step) and keeps the
  // solution as the next warm start. Throws NumericalError (module "mooring", time t + dt, the
  // line and quantity, a hint) on a non-finite pose or when a line has no equilibrium.
  static void advance(const Params& p, const Input& u, double t, double dt, State& s);

  // Loads at the pose in `u`, warm-started from `s`; no side effect.
  static Output outputs(const Params& p, const Input& u, const State& s);

  // outputs() and advance() in one solve: the loads at `u`, with `s` updated to warm-start the next call.
  static Output evaluate(const Params& p, const Input& u, State& s);

  // MoorFxi … MoorMzi, then per line i = 1…n: FAIRTENi, ANCHTENi, FAIRHi, FAIRVi.
  static std::vector<ChannelInfo> channels(const Params& p);

  // Values of channels(p), in that order, into `values` (size must match; InputError otherwise).
  static void channel_values(const Params& p, const Output& y, std::span<double> values);
};

}  // namespace fowtsim::mooring
