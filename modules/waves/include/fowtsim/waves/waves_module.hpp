#pragma once
// The waves module in the module contract (DESIGN.md §2): it writes the wave-elevation channels
// Wave1Elev … Wave9Elev at the deck's probes (OpenFAST names; m, + up from the still-water level,
// incident wave at a fixed (x, y) of the inertial frame). The sea itself is time-explicit: State
// holds only the time. Kinematics for other modules come from Params::field (direct evaluation)
// or from a PrecomputedKinematics built by the driver on the points a scene needs.
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "fowtsim/core/channels.hpp"
#include "fowtsim/waves/precomputed_kinematics.hpp"
#include "fowtsim/waves/wave_field.hpp"
#include "fowtsim/waves/wave_params.hpp"

namespace fowtsim::waves {

struct Waves {
  struct Params {
    std::shared_ptr<const WaveField> field;               // the sea, built from the deck values
    std::shared_ptr<const PrecomputedKinematics> probes;  // η series at the elevation probes
  };
  struct State {
    double time_s = 0.0;                                   // time of the last advance [s]
  };
  struct Input {};                                         // the incident sea needs no input
  struct Output {
    std::array<double, kMaxElevationProbes> elevation_m{};  // η at probe i (Wave{i+1}Elev) [m]
    std::size_t probe_count = 0;                             // probes in use (1 … 9)
  };

  // Validates (InputError listing every problem), synthesises the sea and the probe series.
  static Params make_params(const WaveParams& waves);
  static State make_state(const Params& params);
  static void advance(const Params& params, const Input& input, double t, double dt, State& state);
  static Output outputs(const Params& params, const Input& input, const State& state);
  static std::vector<ChannelInfo> channels(const Params& params);
};

}  // namespace fowtsim::waves
