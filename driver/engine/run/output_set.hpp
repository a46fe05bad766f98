#pragma once
// The output files of one run (HDF5, OpenFAST text .out, OpenFAST binary .outb, and tables the run
// computed whole before its time loop), fed together, and how their names are chosen. A run owns its files:
// - it holds the name's lock (run/output_lock.hpp) from before the first file is touched to the
//   end, so a second run on the same name stops at once and names the holder;
// - files are written under a temporary name in the same folder (runs/x.running.h5 for
//   runs/x.h5) and renamed to their final name when the run ends (completed, failed or
//   interrupted), so a good file of an earlier run is replaced only by a run that started: a deck
//   or option error found before the first row leaves it untouched;
// - a temporary left by a run that died without closing it (SIGKILL, power loss) is never
//   overwritten: it is kept as x.unfinished.h5 (x.unfinished.2.h5, …) and the summary says so;
// - disk space for closing the files is held back (run/disk_reserve.hpp), so on a full disk the
//   run stops with every row it computed written and a status saying why.
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "fowtsim/io/output_sink.hpp"
#include "run/disk_reserve.hpp"
#include "run/output_lock.hpp"
#include "run/run_types.hpp"

namespace fowtsim::driver {

// Output names of a request: no -o gives runs/<deck file stem> (bd_driver.inp → runs/bd_driver),
// except for a restart, whose output is the checkpoint's run's own (left unset here);
// an -o ending in .h5, .out or .outb is taken as the file name: its extension is removed from
// output_base and, when --out-format is absent, picks the format (overriding the deck's
// output.format); with --out-format both it only names the pair (x.h5 → x.h5 and x.out). An
// extension that contradicts --out-format (including .outb with both) is an InputError. Other
// extensions are kept (x.v2 → x.v2.h5).
RunRequest resolve_output_names(const RunRequest& request);

// `path` without a trailing extension from `extensions` (compared case-insensitively), and that
// extension ("" when none matched).
std::pair<std::filesystem::path, std::string> split_known_extension(const std::filesystem::path& path,
                                                                    const std::vector<std::string>& extensions);

// The temporary name `final_path` is written under while the run is going.
std::filesystem::path running_path(const std::filesystem::path& final_path);

// A file a run computes whole before its time loop (the slender scene's spectra): named
// base + suffix and owned like the time series, so it cannot be clobbered by a second run or left
// half-written under its final name.
struct WholeFile {
  std::string suffix;  // e.g. ".amplitude.csv"
  std::string bytes;
};

class OutputSet {
 public:
  // format: "h5", "out", "outb", "both" (.h5 and .out) or "none" (only `whole`); files are
  // base + ".h5" / ".out" / ".outb", then base + each whole file's suffix, then base + each of
  // `end_suffixes`: tables complete only when the run is (the slender scene's profiles, statistics
  // over the whole run), written by write_end_files. The folder is created. Takes the lock and
  // moves a dead run's temporaries aside; a final name that is a folder is an InputError. Creates
  // no output file yet.
  OutputSet(const std::filesystem::path& base, const std::string& format, std::vector<WholeFile> whole = {},
            std::vector<std::string> end_suffixes = {});
  // Without finish(): the writers close their files (status "incomplete"); files holding at
  // least one row get their final name, files without any are removed. Never throws.
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // Writes the whole files under their running names (durable_file.hpp: complete and fsync'ed or
  // absent), holds back disk space for closing the time series (fowtsim::Error if the disk cannot
  // spare it), then creates them. An .outb's cut channel names are added to notes().
  void begin(const std::vector<ChannelInfo>& channels, const io::RunMetadata& metadata);
  // A write that fails frees the held-back space first, so the rows stay buffered for finish();
  // the error then says whether the disk is full.
  void append(double time_s, std::span<const double> values);
  // Every row appended so far on the disk (written and fsync'ed): a checkpoint written after this
  // is never ahead of the rows.
  void sync();
  // The end tables' bytes, one per end suffix in order, written under their running names
  // (complete and fsync'ed or absent). Only a run that took its last step calls it: a run that
  // fails or is interrupted leaves no end table — and removes an earlier run's of the same name,
  // which would not describe the rows beside it.
  void write_end_files(const std::vector<std::string>& bytes);
  // Closes every file with `end` and renames it to its final name; if the run completed, the files
  // named by adopt() are then removed.
  void finish(const io::RunEnd& end);
  // `file` (a dead run's temporary set aside) is continued by this output: removed once this
  // output holds the whole run.
  void adopt(const std::filesystem::path& file) { adopted_.push_back(file); }

  const std::vector<std::filesystem::path>& paths() const { return paths_; }                  // final names
  const std::vector<std::filesystem::path>& running_paths() const { return running_paths_; }  // while running
  const std::vector<std::filesystem::path>& set_aside() const { return set_aside_; }  // dead runs' temporaries, kept
  const std::vector<std::string>& notes() const { return notes_; }  // for the run's summary
  std::vector<std::filesystem::path> end_paths() const {  // final names of the end tables
    return {paths_.end() - static_cast<std::ptrdiff_t>(end_count_), paths_.end()};
  }

 private:
  std::string rename_all() noexcept;  // running → final names; what failed, or ""
  void remove_stale_end_files() noexcept;  // no end table written: an earlier run's are removed
  template <class Write>
  void guarded(Write&& write);  // runs `write`; on failure frees the reserve and says why

  OutputLock lock_;  // first: taken before anything else is touched, released last
  std::filesystem::path base_;
  DiskReserve reserve_;
  std::vector<std::unique_ptr<io::OutputSink>> sinks_;  // the time series: the first sinks_.size() paths
  std::vector<std::string> whole_bytes_;                // the whole files: the paths after them
  std::vector<std::filesystem::path> paths_;
  std::vector<std::filesystem::path> running_paths_;
  std::vector<std::filesystem::path> set_aside_;
  std::vector<std::filesystem::path> adopted_;
  std::vector<std::string> notes_;
  std::size_t end_count_ = 0;  // the end tables: the last end_count_ paths
  bool end_written_ = false;
  std::size_t rows_ = 0;
  bool finished_ = false;
};

}  // namespace fowtsim::driver
