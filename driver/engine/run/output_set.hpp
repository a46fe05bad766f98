#pragma once
// The output files of one run (HDF5 and/or OpenFAST text), fed together, and how their names are
// chosen.
//
// Files are written under a temporary name in the same folder (runs/x.running.h5 for runs/x.h5)
// and renamed to their final name when the run ends (completed, failed or interrupted), so a
// good file of an earlier run is replaced only by a run that started: a deck or option error found
// before the first row leaves it untouched. A live run is watched through the temporary name.
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "fowtsim/io/output_sink.hpp"
#include "run/run_types.hpp"

namespace fowtsim::driver {

// Output names of a request: no -o gives runs/<deck file stem> (bd_driver.inp → runs/bd_driver);
// an -o ending in .h5 or .out is taken as the file name: its extension is removed from
// output_base and, when --out-format is absent, picks the format (overriding the deck's
// output.format); with --out-format both it only names the pair (x.h5 → x.h5 and x.out). An
// extension that contradicts --out-format h5|out is an InputError. Other extensions are kept
// (x.v2 → x.v2.h5).
RunRequest resolve_output_names(const RunRequest& request);

// `path` without a trailing extension from `extensions` (compared case-insensitively), and that
// extension ("" when none matched).
std::pair<std::filesystem::path, std::string> split_known_extension(const std::filesystem::path& path,
                                                                    const std::vector<std::string>& extensions);

// The temporary name `final_path` is written under while the run is going.
std::filesystem::path running_path(const std::filesystem::path& final_path);

class OutputSet {
 public:
  // format: "h5", "out" or "both"; files are base + ".h5" / ".out"; the directory is created.
  OutputSet(const std::filesystem::path& base, const std::string& format);
  // Without finish(): the writers close their files (HDF5 status "incomplete"); files holding at
  // least one row get their final name, files without any are removed. Never throws.
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  void begin(const std::vector<ChannelInfo>& channels, const io::RunMetadata& metadata);
  void append(double time_s, std::span<const double> values);
  // Closes every file with `end` and renames it to its final name.
  void finish(const io::RunEnd& end);
  const std::vector<std::filesystem::path>& paths() const { return paths_; }                  // final names
  const std::vector<std::filesystem::path>& running_paths() const { return running_paths_; }  // while running

 private:
  std::string rename_all() noexcept;  // running → final names; what failed, or ""

  std::vector<std::unique_ptr<io::OutputSink>> sinks_;
  std::vector<std::filesystem::path> paths_;
  std::vector<std::filesystem::path> running_paths_;
  std::size_t rows_ = 0;
  bool finished_ = false;
};

}  // namespace fowtsim::driver
