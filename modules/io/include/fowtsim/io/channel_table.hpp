#pragma once
// A table of output channels read back from a file (ours or OpenFAST's), one column per channel.
// Readers normalise it so that column 0 is always the time channel, named "Time" with unit "s",
// whatever the file called it; that lets comparisons treat every source the same way.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fowtsim::io {

struct ChannelTable {
  std::vector<std::string> names;            // channel names; names[0] == "Time"
  std::vector<std::string> units;            // units without parentheses, e.g. "kN-m"; units[0] == "s"
  std::vector<std::vector<double>> columns;  // columns[c][row]: value of channel c at row; all columns
                                             // have rows() entries; columns[0] is time [s]
  std::string description;                   // free text from the file header (program, deck, ...)
  std::string status;                        // how the run that wrote the file ended, as the file says
                                             // ("completed", "interrupted at t = …", "failed: …",
                                             // "running"); empty when the file does not say (OpenFAST's)
  std::vector<std::string> warnings;         // what the reader read past (e.g. a row cut short)

  // Number of time rows (0 for an empty table).
  std::size_t rows() const;
  // Column index of the channel with exactly this name, if present.
  std::optional<std::size_t> find(std::string_view name) const;
  // The time column [s]; throws fowtsim::Error if the table has no columns.
  const std::vector<double>& time() const;
};

// What a reader of `table` should be told: the reader's warnings, and whether the file says its
// run did not complete (a status neither empty nor "completed"), naming `source`.
std::vector<std::string> reading_warnings(const ChannelTable& table, const std::string& source);

// Checks the shape of a freshly read table (as many units and columns as names, columns of equal
// length) and normalises its first column to the time channel: a first name equal to "Time"
// (any letter case) becomes "Time" with unit "s". Throws InputError naming `source` (a file path)
// if the shape is wrong or the first channel is not time.
void normalise_time_channel(ChannelTable& table, const std::string& source);

}  // namespace fowtsim::io
