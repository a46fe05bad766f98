#include "run/output_set.hpp"

#include <algorithm>
#include <cctype>
#include <exception>
#include <stdexcept>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/hdf5_writer.hpp"
#include "fowtsim/io/outb_writer.hpp"
#include "fowtsim/io/text_out_writer.hpp"
#include "run/durable_file.hpp"

namespace fowtsim::driver {

std::pair<std::filesystem::path, std::string> split_known_extension(const std::filesystem::path& path,
                                                                    const std::vector<std::string>& extensions) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) return {path, ""};
  std::filesystem::path base = path;
  base.replace_extension();
  return {base, ext};
}

RunRequest resolve_output_names(const RunRequest& request) {
  RunRequest r = request;
  if (!r.output_base) {
    // A restart continues the output of the run that wrote its checkpoint (recorded in it).
    if (!r.restart_path) r.output_base = std::filesystem::path("runs") / r.deck_path.stem();
    return r;
  }
  const auto [base, ext] = split_known_extension(*r.output_base, {".h5", ".out", ".outb"});
  if (ext.empty()) return r;
  const std::string named = ext.substr(1);  // "h5", "out" or "outb"
  const bool in_pair = named != "outb";     // "both" is .h5 and .out
  if (r.output_format && *r.output_format != named && !(*r.output_format == "both" && in_pair))
    throw InputError({"run", std::nullopt, "-o",
                      fmt::format("drop the extension, or use --out-format {}{}", named, in_pair ? " or both" : "")},
                     fmt::format("-o {} names a .{} file but --out-format is {}", r.output_base->string(), named,
                                 *r.output_format));
  if (!r.output_format) r.output_format = named;
  r.output_base = base;
  return r;
}

std::filesystem::path running_path(const std::filesystem::path& final_path) {
  std::filesystem::path p = final_path;
  p.replace_filename(final_path.stem().string() + ".running" + final_path.extension().string());
  return p;
}

namespace {

// Where a dead run's temporaries are kept: x.unfinished.h5 (and .out, .outb), or x.unfinished.2.*,
// … — one number for the set, the first under which none of its files exists.
std::vector<std::filesystem::path> unfinished_names(const std::vector<std::filesystem::path>& final_paths) {
  for (int n = 1;; ++n) {
    std::vector<std::filesystem::path> names;
    for (const auto& f : final_paths) {
      std::filesystem::path p = f;
      p.replace_filename(f.stem().string() + ".unfinished" + (n == 1 ? "" : fmt::format(".{}", n)) + f.extension().string());
      names.push_back(p);
    }
    if (std::none_of(names.begin(), names.end(), [](const auto& p) { return std::filesystem::exists(p); })) return names;
  }
}

// Disk space to hold back: a full block of rows in every file plus the files' closing records
// (HDF5: chunk and object-header updates per dataset; text: the status line; .outb: nothing, its
// header is rewritten in place).
std::uint64_t reserve_bytes(std::size_t channels, const std::vector<std::filesystem::path>& files) {
  constexpr std::uint64_t kRowsPerBlock = 1024, kPerDatasetMetadata = 4096, kMargin = std::uint64_t{1} << 20;
  const std::uint64_t columns = channels + 1;
  std::uint64_t bytes = kMargin;
  for (const auto& f : files) {
    if (f.extension() == ".h5") bytes += columns * (kRowsPerBlock * 8 + kPerDatasetMetadata);
    if (f.extension() == ".out") bytes += columns * kRowsPerBlock * 20;  // " d.dddddddddE+XX\t" per value
    if (f.extension() == ".outb") bytes += columns * kRowsPerBlock * 8;
  }
  return bytes;
}

}  // namespace

OutputSet::OutputSet(const std::filesystem::path& base, const std::string& format, std::vector<WholeFile> whole,
                     std::vector<std::string> end_suffixes)
    : lock_(base), base_(base), end_count_(end_suffixes.size()) {
  if (format == "h5" || format == "both") paths_.push_back(std::filesystem::path(base.string() + ".h5"));
  if (format == "out" || format == "both") paths_.push_back(std::filesystem::path(base.string() + ".out"));
  if (format == "outb") paths_.push_back(std::filesystem::path(base.string() + ".outb"));
  const std::size_t series = paths_.size();
  for (WholeFile& w : whole) {
    paths_.push_back(std::filesystem::path(base.string() + w.suffix));
    whole_bytes_.push_back(std::move(w.bytes));
  }
  for (const std::string& suffix : end_suffixes) paths_.push_back(std::filesystem::path(base.string() + suffix));
  for (const auto& p : paths_) {
    if (std::filesystem::is_directory(p))
      throw InputError({"run", std::nullopt, "-o", "a file name, not a folder's"},
                       fmt::format("the output {} is a folder", p.string()));
    running_paths_.push_back(running_path(p));
  }
  // Holding the lock, a temporary already there belongs to a run that died without closing it.
  const std::vector<std::filesystem::path> unfinished = unfinished_names(paths_);
  for (std::size_t i = 0; i < running_paths_.size(); ++i) {
    const std::filesystem::path& p = running_paths_[i];
    if (!std::filesystem::exists(p)) continue;
    const std::filesystem::path& kept = unfinished[i];
    std::filesystem::rename(p, kept);
    set_aside_.push_back(kept);
    notes_.push_back(fmt::format("{} was left by a run that stopped without closing it (killed?): kept as {}", p.string(),
                                 kept.string()));
  }
  for (std::size_t i = 0; i < series; ++i) {
    const std::filesystem::path& p = running_paths_[i];
    if (p.extension() == ".h5")
      sinks_.push_back(std::make_unique<io::Hdf5Writer>(p));
    else if (p.extension() == ".outb")
      sinks_.push_back(std::make_unique<io::OutbWriter>(p));
    else
      sinks_.push_back(std::make_unique<io::TextOutWriter>(p));
  }
}

OutputSet::~OutputSet() {
  if (finished_) return;
  reserve_.release();
  sinks_.clear();  // each writer closes its file, keeping the rows appended so far
  if (rows_ > 0) {
    rename_all();
    remove_stale_end_files();
  } else {
    std::error_code ignored;
    for (const auto& p : running_paths_) std::filesystem::remove(p, ignored);
  }
}

template <class Write>
void OutputSet::guarded(Write&& write) {
  try {
    write();
  } catch (const std::exception& e) {
    const std::filesystem::path folder = base_.has_parent_path() ? base_.parent_path() : ".";
    const std::uint64_t free = free_bytes(folder);
    if (!reserve_.release()) throw;
    // The reserve is free now: finish() can write the buffered rows and the status.
    if (free < (std::uint64_t{1} << 20))
      throw Error({"output", std::nullopt, folder.string(), "free some space, then restart from a checkpoint or rerun"},
                  fmt::format("the disk holding {} is full ({} bytes free): {}", folder.string(), free, e.what()));
    throw;
  }
}

void OutputSet::begin(const std::vector<ChannelInfo>& channels, const io::RunMetadata& metadata) {
  for (std::size_t i = 0; i < whole_bytes_.size(); ++i) write_file_atomically(running_paths_[sinks_.size() + i], whole_bytes_[i]);
  reserve_ = DiskReserve(running_path(std::filesystem::path(base_.string() + ".reserve")), reserve_bytes(channels.size(), paths_));
  for (const auto& p : paths_)
    if (p.extension() == ".outb")
      if (const std::string note = io::outb_name_note(channels); !note.empty()) notes_.push_back(p.string() + ": " + note);
  guarded([&] {
    for (auto& sink : sinks_) sink->begin(channels, metadata);
  });
}

void OutputSet::append(double time_s, std::span<const double> values) {
  ++rows_;  // counted first: a row that fails to reach the disk is still buffered for finish()
  guarded([&] {
    // Every sink gets the row even when one fails, so they all hold the same rows at finish().
    std::exception_ptr failure;
    for (auto& sink : sinks_) {
      try {
        sink->append(time_s, values);
      } catch (...) {
        if (!failure) failure = std::current_exception();
      }
    }
    if (failure) std::rethrow_exception(failure);
  });
}

void OutputSet::sync() {
  guarded([&] {
    for (auto& sink : sinks_) sink->flush();
    // The end tables are written (and synced) whole by write_end_files, after the last step.
    for (std::size_t i = 0; i + end_count_ < running_paths_.size(); ++i) sync_file(running_paths_[i]);
  });
}

void OutputSet::write_end_files(const std::vector<std::string>& bytes) {
  if (bytes.size() != end_count_) throw std::logic_error("OutputSet::write_end_files: one table per end suffix");
  const std::size_t first = running_paths_.size() - end_count_;
  for (std::size_t i = 0; i < end_count_; ++i) write_file_atomically(running_paths_[first + i], bytes[i]);
  end_written_ = true;
}

void OutputSet::remove_stale_end_files() noexcept {
  if (end_written_) return;
  std::error_code ignored;
  for (const auto& p : end_paths()) std::filesystem::remove(p, ignored);
}

void OutputSet::finish(const io::RunEnd& end) {
  finished_ = true;
  reserve_.release();
  remove_stale_end_files();
  try {
    for (auto& sink : sinks_) sink->finish(end);
  } catch (...) {
    sinks_.clear();
    rename_all();
    throw;
  }
  const std::string failed = rename_all();
  if (!failed.empty())
    throw Error({"run", std::nullopt, "output", "check the output folder"}, "cannot rename the output: " + failed);
  // Only a completed output holds every row an adopted file had (an interrupted one may end before it).
  std::error_code ignored;
  if (end.status == "completed")
    for (const auto& p : adopted_) std::filesystem::remove(p, ignored);
}
std::string OutputSet::rename_all() noexcept {
  std::string failed;
  for (std::size_t i = 0; i < paths_.size(); ++i) {
    std::error_code error;
    if (!std::filesystem::exists(running_paths_[i], error)) continue;
    std::filesystem::rename(running_paths_[i], paths_[i], error);
    if (error)
      failed += (failed.empty() ? "" : "; ") + running_paths_[i].string() + " → " + paths_[i].string() + ": " + error.message();
  }
  return failed;
}

}  // namespace fowtsim::driver
