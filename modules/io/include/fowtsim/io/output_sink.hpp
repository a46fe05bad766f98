#pragma once
// The interface the driver writes output channels through (DESIGN.md §6), and the flush policy
// its file writers share. A sink receives the channel list once, then one row per output time,
// then the end-of-run record; it must keep everything appended so far even if the run dies.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "fowtsim/core/channels.hpp"

namespace fowtsim::io {

// What a run records about itself at the start, so an output file can be traced back to the exact
// inputs that produced it (and rerun bit-identically).
struct RunMetadata {
  std::string version;                // fowtsim version that wrote the file, e.g. "0.1.0"
  std::string deck_path;              // path of the top-level input deck, as given on the command line
  std::string deck_hash;              // hash of the fully resolved deck text (includes expanded), hex
  std::vector<std::uint64_t> seeds;   // random seeds used (turbulence, irregular waves, ...), in deck order
  double dt_s = 0.0;                  // small (module) time step Δt [s]
  double dt_coupling_s = 0.0;         // large coupling time step ΔT [s]
  std::vector<std::pair<std::string, std::string>> extra;  // further key/value pairs, written as-is
};

// What a run records about itself at the end.
struct RunEnd {
  double wall_time_s = 0.0;  // wall-clock duration of the run [s]
  std::string status;        // "completed", or "failed: <message>"
  double end_time_s = 0.0;   // last simulated time reached [s]
  std::vector<std::string> warnings;  // what the run summary warns about (HDF5: one per line)
};

class OutputSink {
 public:
  OutputSink() = default;
  OutputSink(const OutputSink&) = delete;
  OutputSink& operator=(const OutputSink&) = delete;
  virtual ~OutputSink() = default;

  // Declares the channels (without Time, which every sink writes first) and the run metadata.
  // Called once, before the first append.
  virtual void begin(const std::vector<ChannelInfo>& channels, const RunMetadata& metadata) = 0;
  // One output row: simulation time [s] and one value per declared channel, in declaration order.
  virtual void append(double time_s, std::span<const double> values) = 0;
  // Pushes every appended row to the file now (e.g. before a risky step, or on a signal).
  virtual void flush() = 0;
  // Writes the end-of-run record, flushes and closes. No append after finish.
  virtual void finish(const RunEnd& end) = 0;
};

// When an incremental writer should push its buffered rows to disk: when the buffer holds a full
// block, or when more than `max_interval` of wall clock has passed since the last flush (so a
// killed process loses little). The clock is read only every `kClockCheckEvery` appends, which
// keeps the per-append cost to a counter increment.
class FlushPolicy {
 public:
  static constexpr std::size_t kClockCheckEvery = 64;

  explicit FlushPolicy(std::size_t rows_per_block,
                       std::chrono::steady_clock::duration max_interval = std::chrono::seconds(2))
      : rows_per_block_(rows_per_block == 0 ? 1 : rows_per_block), max_interval_(max_interval) {}

  std::size_t rows_per_block() const { return rows_per_block_; }

  // Call once per append with the number of rows now buffered; true means "flush now".
  bool due(std::size_t buffered_rows) {
    if (buffered_rows >= rows_per_block_) return true;
    if (++appends_since_check_ < kClockCheckEvery) return false;
    appends_since_check_ = 0;
    return std::chrono::steady_clock::now() - last_flush_ >= max_interval_;
  }

  // Call after every flush, whatever triggered it.
  void flushed() {
    appends_since_check_ = 0;
    last_flush_ = std::chrono::steady_clock::now();
  }

 private:
  std::size_t rows_per_block_;
  std::chrono::steady_clock::duration max_interval_;
  std::size_t appends_since_check_ = 0;
  std::chrono::steady_clock::time_point last_flush_ = std::chrono::steady_clock::now();
};

}  // namespace fowtsim::io
