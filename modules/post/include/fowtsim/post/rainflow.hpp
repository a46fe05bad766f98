#pragma once
// Rainflow cycle counting, ASTM E1049-85 (reapproved 2017), "Standard Practices for Cycle Counting
// in Fatigue Analysis", §5.4.4 "Rainflow Counting", by the equivalent four-point formulation:
//  1. the series is reduced to its turning points (peaks and valleys; plateaus keep one point);
//  2. every four consecutive turning points a, b, c, d on a stack with |b − c| ≤ |a − b| and
//     |b − c| ≤ |c − d| close one full cycle of range |b − c| (b and c are removed);
//  3. what remains on the stack is the residue: each range between consecutive residue points is
//     a half cycle — what the three-point method's steps 5 and 6 count as half cycles.
// The two formulations give the same cycle table (checked on the standard's example, Fig. 6).
#include <span>
#include <vector>

namespace fowtsim::post {

// How the residue (unclosed ranges) is counted.
enum class ResidueCounting {
  half_cycles,  // 0.5 each: ASTM E1049-85 §5.4.4.6, MLife (UCMult = 0.5), wetb — the default
  full_cycles,  // 1.0 each: MLife with UCMult = 1, the conservative choice pCrunch users expect
};

struct RainflowCycle {
  double range = 0.0;  // peak-to-valley range |b − c|, channel unit
  double mean = 0.0;   // (b + c) / 2, channel unit
  double count = 0.0;  // 1 for a closed cycle; 0.5 or 1 for a residue range (ResidueCounting)
};

// The peaks and valleys of `values` in order: the first and last samples, and every sample where
// the series turns; equal neighbours (plateaus) collapse to one point. NaN is not allowed.
std::vector<double> turning_points(std::span<const double> values);

// The rainflow cycles of `values` (any series; turning points are extracted first): closed cycles
// in the order they close, then the residue ranges in time order. Identical cycles are not merged
// (no binning): the DEL sums over them exactly.
std::vector<RainflowCycle> rainflow_cycles(std::span<const double> values,
                                           ResidueCounting residue = ResidueCounting::half_cycles);

}  // namespace fowtsim::post
