#pragma once
// The ultimate-load table of a sweep, as certifiers ask for it: per channel and sense (maximum,
// minimum), the design value γ_f F_k, the characteristic value F_k, the governing load case and
// realisation, the time of the extreme and the concurrent values of the other channels then.
//
// F_k per load case (a group's factor combination, its realisations together): with at least six
// completed realisations (the turbulent presets' kPresetSeeds) the mean of their extremes, as
// IEC 61400-1 allows for turbulent load cases; with fewer, the largest extreme. γ_f is the
// group's partial safety factor for loads (its preset's: N 1.35, A 1.1; IEC 61400-1 ed. 4
// Table 3), on channels in force or moment units only (a motion or an angle keeps γ_f = 1).
// Only groups whose analysis includes U enter. The governing load case is the one with
// the largest |γ_f F_k| in the sense; within it the realisation with the extreme itself.
#include <cstddef>
#include <string>
#include <vector>

namespace fowtsim::driver::sweep {

struct LoadTable;
struct LoadTableRow;
struct SweepSpec;

struct UltimateLoad {
  enum class Sense { maximum, minimum };
  std::size_t channel = 0;             // index in LoadTable::channels
  Sense sense = Sense::maximum;
  double design_value = 0.0;           // γ_f F_k, channel unit
  double characteristic_value = 0.0;   // F_k, channel unit
  double partial_safety_factor = 1.0;  // γ_f of the governing group
  std::size_t realisations = 0;        // completed realisations behind F_k
  bool mean_of_realisations = false;   // F_k is their mean extreme (≥ 6), else their largest
  const LoadTableRow* governing = nullptr;  // the realisation with the extreme
  double time_s = 0.0;                 // when it happens in that realisation [s]
  std::vector<double> concurrent;      // every LoadTable::channels value then (NaN: not in the outputs)
};

// Realisations a load case needs for the mean of extremes (IEC 61400-1: six 10-minute ones).
inline constexpr std::size_t kRealisationsForMean = 6;

// One maximum and one minimum per channel with a completed ultimate case; none for the others.
std::vector<UltimateLoad> ultimate_loads(const LoadTable& table, const SweepSpec& spec);

}  // namespace fowtsim::driver::sweep
