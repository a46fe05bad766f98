#pragma once
// The rows a restarted run's output begins with: those the interrupted run wrote before the
// checkpoint's time, so that the restarted output holds the whole run (the rows from the
// checkpoint on are computed again, bit-identically) and a restart never loses rows.
#include <filesystem>
#include <string>
#include <vector>

#include "fowtsim/core/channels.hpp"
#include "fowtsim/io/channel_table.hpp"

namespace fowtsim::driver {

class OutputSet;

struct EarlierRows {
  io::ChannelTable table;            // Time and `channels`, rows before the restart time
  std::filesystem::path source;      // the file they come from (empty: none found)
  std::vector<std::string> notes;    // for the summary: where the rows came from, what is missing
};

// Looks for the interrupted run's output `old_base` (.h5 first, then .outb, then .out; the temporaries of a
// run that died; when old_base is this run's own name, the temporaries `outputs` set aside) of
// the same deck (`deck_hash`) and the same channels, and returns its rows before `t_restart_s`.
// A file whose rows stop more than `row_interval_s` before the restart leaves a gap, said in the
// notes. Throws InputError if a live run still writes old_base.
EarlierRows earlier_rows(const std::filesystem::path& old_base, const OutputSet& outputs,
                         const std::vector<ChannelInfo>& channels, const std::string& deck_hash, double t_restart_s,
                         double row_interval_s);

}  // namespace fowtsim::driver
