#include "run/earlier_rows.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/outb_writer.hpp"
#include "fowtsim/io/readers.hpp"
#include "run/output_lock.hpp"
#include "run/output_set.hpp"

namespace fowtsim::driver {
namespace {

// The files that may hold the interrupted run's rows, most trusted first.
std::vector<std::filesystem::path> candidates(const std::filesystem::path& old_base, const OutputSet& outputs) {
  std::vector<std::filesystem::path> files;
  const std::filesystem::path h5 = old_base.string() + ".h5", out = old_base.string() + ".out", outb = old_base.string() + ".outb";
  if (std::filesystem::absolute(old_base).lexically_normal() ==
      std::filesystem::absolute(outputs.paths().front()).replace_extension().lexically_normal()) {
    files = outputs.set_aside();  // our own name: a dead run's temporaries were just moved aside
    // Lossless first: .h5 and .outb hold every bit, .out 10 digits.
    std::stable_partition(files.begin(), files.end(), [](const auto& f) { return f.extension() != ".out"; });
  } else {
    if (OutputLock::held_by_another_run(old_base))
      throw InputError({"run", std::nullopt, "--restart", "wait for that run to end"},
                       fmt::format("the run that wrote the checkpoint still writes {}", old_base.string()));
    files = {running_path(h5), running_path(outb), running_path(out)};
  }
  files.push_back(h5);
  files.push_back(outb);
  files.push_back(out);
  return files;
}

// An .outb holds the names cut to io::kOutbNameLength characters.
bool same_channels(const io::ChannelTable& table, const std::vector<ChannelInfo>& channels, const std::filesystem::path& file) {
  if (table.names.size() != channels.size() + 1) return false;
  const std::size_t length = file.extension() == ".outb" ? io::kOutbNameLength : std::string::npos;
  for (std::size_t c = 0; c < channels.size(); ++c)
    if (table.names[c + 1] != channels[c].name.substr(0, length)) return false;
  return true;
}

}  // namespace

EarlierRows earlier_rows(const std::filesystem::path& old_base, const OutputSet& outputs,
                         const std::vector<ChannelInfo>& channels, const std::string& deck_hash, double t_restart_s,
                         double row_interval_s) {
  EarlierRows best;
  double best_end = -1.0;
  std::vector<std::string> skipped;
  for (const std::filesystem::path& file : candidates(old_base, outputs)) {
    if (!std::filesystem::is_regular_file(file)) continue;
    io::ChannelTable table;
    try {
      table = io::read_channels(file);
    } catch (const std::exception& e) {
      skipped.push_back(fmt::format("{} (unreadable: {})", file.string(), e.what()));
      continue;
    }
    // Our formats carry the deck hash in their header (HDF5 attribute, .out line 3, .outb description).
    if (table.description.find(deck_hash) == std::string::npos || !same_channels(table, channels, file)) {
      skipped.push_back(fmt::format("{} (another deck or other channels)", file.string()));
      continue;
    }
    const double end = table.rows() ? table.time().back() : -1.0;
    if (end <= best_end) continue;
    best = {std::move(table), file, {}};
    best_end = end;
    if (best_end >= t_restart_s - row_interval_s * (1.0 + 1e-9)) break;  // reaches the checkpoint: no gap
  }
  for (const std::string& s : skipped) best.notes.push_back("not continued: " + s);
  if (best.source.empty()) {
    best.notes.push_back(fmt::format("no output of the interrupted run was found at {}: the output starts at t = {:.6g} s",
                                     old_base.string(), t_restart_s));
    return best;
  }
  // Rows strictly before the restart time (half a row interval of margin against rounding): the
  // restarted run writes the checkpoint's row itself.
  const std::vector<double>& time = best.table.time();
  const std::size_t keep = static_cast<std::size_t>(
      std::lower_bound(time.begin(), time.end(), t_restart_s - 0.5 * row_interval_s) - time.begin());
  for (auto& column : best.table.columns) column.resize(keep);
  best.notes.push_back(fmt::format("continues {}: {} rows before t = {:.6g} s copied from it", best.source.string(), keep,
                                   t_restart_s));
  if (best_end < t_restart_s - row_interval_s * (1.0 + 1e-9))
    best.notes.push_back(fmt::format("rows between t = {:.6g} s and the checkpoint at {:.6g} s are missing: {} ends there",
                                     best_end, t_restart_s, best.source.string()));
  if (best.source.extension() == ".out" && outputs.paths().front().extension() != ".out")
    best.notes.push_back("the copied rows come from the text output: rounded to its 10 significant digits");
  return best;
}

}  // namespace fowtsim::driver
