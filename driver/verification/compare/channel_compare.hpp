#pragma once
// Channel-by-channel comparison of two output tables (issue 2, item 7): how users check a run
// against a reference run (ours, OpenFAST's) and how the regression tier works.
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fowtsim/io/channel_table.hpp"

namespace fowtsim::driver {

// Pass when |test − ref| ≤ atol + range_atol·(max ref − min ref) + rtol·|ref| at every aligned
// sample (numpy.isclose style, as in OpenFAST's r-test, whose absolute part also scales with each
// channel's size).
struct ChannelTolerance {
  double rtol = 1e-6;        // relative tolerance [-]
  double atol = 1e-9;        // absolute tolerance [channel unit]
  double range_atol = 0.0;   // absolute tolerance per unit of the reference channel's range [-]
};

// The default for code-to-code checks: 0.1 % of the value plus 0.1 % of the channel's range, so a
// channel that crosses zero is not held to a relative bound at its zero crossings.
inline constexpr ChannelTolerance kCodeToCodeTolerance{1e-3, 0.0, 1e-3};

struct CompareOptions {
  ChannelTolerance default_tolerance = kCodeToCodeTolerance;  // for channels not listed below
  std::map<std::string, ChannelTolerance> tolerances;  // per-channel overrides
  std::vector<std::string> channels;  // channels to compare; empty = all common to both (not Time).
                                      // A listed channel missing from either file fails the comparison.
  std::optional<std::pair<double, double>> window;  // compare only over [t0, t1] (skip start-up) [s]
  std::map<std::string, std::string> aliases;  // another name of a channel in the other file (MAP++ T[1] ↔ FAIRTEN1)
  // Compare mean, std, min and max per channel instead of sample by sample (the only meaningful
  // comparison of turbulent runs with different seeds); the tolerances apply to each statistic.
  bool statistics = false;
  // With statistics: also the damage-equivalent load of this Wöhler exponent (MLife: rainflow with
  // the residue as half cycles, f_eq 1 Hz over the compared window, no Goodman correction).
  std::optional<double> wohler_exponent;
};

struct ChannelComparison {
  std::string name;
  std::string unit;                 // of the reference
  double max_abs_error = 0;         // max |test − ref| [unit]
  double rms_error_over_rms = 0;    // rms(test − ref) / rms(ref) [-]; NaN when rms(ref) = 0
  double rms_error_over_range = 0;  // rms(test − ref) / (max ref − min ref) [-]; NaN for a constant ref
  double correlation = 0;           // Pearson correlation [-]; NaN when either is constant
  double worst_excess = 0;          // max of |test − ref| − tolerance (≤ 0 passes)
  double worst_time_s = 0;          // time of the worst excess [s]
  bool constant_reference = false;  // the reference channel does not change (ratios undefined)
  // With CompareOptions::statistics: mean, std, min, max and the DEL (NaN unless a Wöhler exponent
  // was given) of reference and test.
  std::array<double, 5> reference_statistics{}, test_statistics{};
  ChannelTolerance tolerance;
  bool pass = false;
};

struct ComparisonReport {
  std::vector<ChannelComparison> channels;       // in the reference's order
  std::vector<std::string> missing_in_test;      // requested/reference channels absent from test
  std::vector<std::string> missing_in_reference; // test channels absent from the reference
  std::vector<std::string> required_missing_names;  // channels asked for and absent (each once)
  bool required_missing = false;                 // a channel the user asked for is absent
  bool statistics = false;                       // statistics compared instead of samples
  std::optional<double> wohler_exponent;         // the DEL's Wöhler exponent, when compared
  double t_start_s = 0, t_end_s = 0;             // compared window (overlap of both files) [s]
  std::size_t samples = 0;                       // reference samples inside the window
  bool pass() const;
};

// Aligns test onto the reference time samples inside the common time window (linear
// interpolation) and compares matching channels. Throws InputError when the files share no
// time window or no channel.
ComparisonReport compare_tables(const io::ChannelTable& reference, const io::ChannelTable& test,
                                const CompareOptions& options);

// Per-channel tolerance file (YAML, OpenFAST regression style):
//   default: {rtol: 1e-6, atol: 1e-9}            # absent: kCodeToCodeTolerance
//   channels:
//     ToySlowPos: {rtol: 1e-5, atol: 1e-8, range_atol: 0}
//   aliases: {FAIRTEN1: "T[1]"}                  # a name in one file, its name in the other
// Listed channels are required. Bad files stop with file:line:col, key and what was expected.
CompareOptions load_tolerance_file(const std::string& path);

}  // namespace fowtsim::driver
