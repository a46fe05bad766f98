#pragma once
// A measured or computed wave-elevation time history at the reference point x = y = 0, from which
// `model: elevation_series` rebuilds the long-crested linear sea (as OpenFAST SeaState WaveMod 5).
// The waves module never reads files (DESIGN.md §1: physics modules depend on core only): the driver
// reads the deck's `file` into this struct, with the file name and the line of each sample so that
// a bad record is reported where the user can fix it.
//
// Rebuilding (WaveField's constructor; README "Replaying a sea"): the N uniform samples
// η_j = η(t₀ + j Δt) span one period D = N Δt of the sea. Their discrete Fourier transform
// X_n = Σ_j η_j e^{−2πi jn/N} gives, for n = 1 … ⌊N/2⌋ (the mean X₀/N is removed), the components
//   A_n = (2/N) X_n e^{−iω_n t₀},   ω_n = 2π n / D   (A_{N/2} = (X_{N/2}/N) e^{−iω_{N/2} t₀} for even N),
// so that η(0, 0, t) = Σ Re[A_n e^{iω_n t}] equals η_j − mean at t = t_j: the record's time column is
// simulation time, and outside [t₀, t₀ + D) the sea repeats with period D. Each component travels
// along the deck's heading with k_n from the exact dispersion relation. Unlike the synthesised seas,
// the Nyquist term of an even N is kept (so the record is reproduced exactly; its sine part, unseen
// at the samples, is taken as zero).
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace fowtsim::waves {

struct ElevationRecord {
  std::vector<double> time_s;       // sample times [s], uniformly spaced, increasing (simulation time)
  std::vector<double> elevation_m;  // η at x = y = 0 [m], + up; the mean is removed when rebuilding
  std::string source;               // where the record comes from (a file name), for messages
  std::vector<std::size_t> lines;   // optional: line of sample j in `source` (1-based), for messages
};

// Samples a record needs (the same floor as the synthesised seas' records).
inline constexpr std::size_t kMinRecordSamples = 8;

// Relative slack of the uniform-sampling check: every time must lie within this fraction of a step
// of the grid t₀ + j Δt, Δt = (t_last − t₀)/(N − 1), and every step within it of Δt. 1 % lets through
// times printed with few digits (an OpenFAST .out at 4 decimals with Δt = 1/30 s is off by 0.15 %),
// and catches a missing, repeated or shifted sample (off by ≥ half a step somewhere).
inline constexpr double kUniformSamplingSlack = 0.01;

// The uniform grid of a valid record.
struct RecordGrid {
  double start_s = 0.0;     // t₀ [s]
  double step_s = 0.0;      // Δt = (t_last − t₀)/(N − 1) [s]
  double duration_s = 0.0;  // D = N Δt: the period of the rebuilt sea [s]
  std::size_t samples = 0;  // N
};

// Checks the record (at least kMinRecordSamples samples, as many times as elevations, every value
// finite, times uniformly spaced and increasing) and returns its grid. Throws InputError (module
// "waves", variable "waves.file") whose message starts with "source:line:" (or "source: sample j")
// at the first bad sample and says what was expected.
RecordGrid check_elevation_record(const ElevationRecord& record);

// The record from two arrays, for callers that build it in memory (source names it in messages).
ElevationRecord make_elevation_record(std::span<const double> time_s, std::span<const double> elevation_m,
                                      std::string source = "elevation record");

}  // namespace fowtsim::waves
