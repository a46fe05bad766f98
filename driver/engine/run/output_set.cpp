#include "run/output_set.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/hdf5_writer.hpp"
#include "fowtsim/io/text_out_writer.hpp"

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
    r.output_base = std::filesystem::path("runs") / r.deck_path.stem();
    return r;
  }
  const auto [base, ext] = split_known_extension(*r.output_base, {".h5", ".out"});
  if (ext.empty()) return r;
  const std::string named = ext.substr(1);  // "h5" or "out"
  if (r.output_format && *r.output_format != "both" && *r.output_format != named)
    throw InputError({"run", std::nullopt, "-o", fmt::format("drop the extension, or use --out-format {} or both", named)},
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

OutputSet::OutputSet(const std::filesystem::path& base, const std::string& format) {
  if (base.has_parent_path()) std::filesystem::create_directories(base.parent_path());
  if (format == "h5" || format == "both") {
    paths_.push_back(std::filesystem::path(base.string() + ".h5"));
    running_paths_.push_back(running_path(paths_.back()));
    sinks_.push_back(std::make_unique<io::Hdf5Writer>(running_paths_.back()));
  }
  if (format == "out" || format == "both") {
    paths_.push_back(std::filesystem::path(base.string() + ".out"));
    running_paths_.push_back(running_path(paths_.back()));
    sinks_.push_back(std::make_unique<io::TextOutWriter>(running_paths_.back()));
  }
}

OutputSet::~OutputSet() {
  if (finished_) return;
  sinks_.clear();  // each writer closes its file, keeping the rows appended so far
  if (rows_ > 0) {
    rename_all();
  } else {
    std::error_code ignored;
    for (const auto& p : running_paths_) std::filesystem::remove(p, ignored);
  }
}

void OutputSet::begin(const std::vector<ChannelInfo>& channels, const io::RunMetadata& metadata) {
  for (auto& sink : sinks_) sink->begin(channels, metadata);
}

void OutputSet::append(double time_s, std::span<const double> values) {
  for (auto& sink : sinks_) sink->append(time_s, values);
  ++rows_;
}

void OutputSet::finish(const io::RunEnd& end) {
  finished_ = true;
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
