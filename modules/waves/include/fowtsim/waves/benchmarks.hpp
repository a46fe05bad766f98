#pragma once
// Cost measurements of the waves module (DESIGN.md §8: printed by a tool, never asserted):
// synthesis of a record on N points, and the cost of one kinematics lookup from the precomputed
// field against direct summation over the components, with the difference between the two.
#include <cstddef>
#include <vector>

#include "fowtsim/core/types.hpp"
#include "fowtsim/waves/wave_params.hpp"

namespace fowtsim::waves::benchmarks {

// The sea of the irregular-sea check: JONSWAP Hs 6 m, Tp 10 s, γ 3.3, 3-hour record,
// dt 0.25 s, depth 320 m (OC3), seed 1.
WaveParams three_hour_jonswap();

// Points on a vertical line through the origin, from z = −120 m (OC3 spar draft) to z = 0,
// evenly spaced: a stand-in for a spar's strip nodes.
std::vector<Vec3> spar_points(std::size_t count);

struct SynthesisRow {
  Stretching stretching = Stretching::none;
  std::size_t points = 0;             // points precomputed
  double field_s = 0.0;               // WaveField construction (phases, dispersion) [s]
  double precompute_s = 0.0;          // PrecomputedKinematics construction (all FFTs) [s]
  double memory_MB = 0.0;             // stored series [MB]
};

struct LookupRow {
  Stretching stretching = Stretching::none;
  std::size_t components = 0;         // components summed by direct evaluation
  double precomputed_ns = 0.0;        // per point per time step [ns]
  double direct_ns = 0.0;             // per point per time step [ns]
  double max_velocity_difference_m_s = 0.0;  // max |v_pre − v_direct| over the sampled lookups
  double velocity_rms_m_s = 0.0;      // RMS |v| over the same lookups (scale of the difference)
};

// Synthesis cost for each point count and both stretching options.
std::vector<SynthesisRow> synthesis_cost(const WaveParams& params, const std::vector<std::size_t>& point_counts);

// Lookup cost on `points` spar points over `steps` time steps of 0.05 s (off the record grid);
// direct summation on a subset of steps (it is slow), both stretching options.
std::vector<LookupRow> lookup_cost(const WaveParams& params, std::size_t points, std::size_t steps);

}  // namespace fowtsim::waves::benchmarks
