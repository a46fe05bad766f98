#include "run/output_set.hpp"

#include "fowtsim/io/hdf5_writer.hpp"
#include "fowtsim/io/text_out_writer.hpp"

namespace fowtsim::driver {

OutputSet::OutputSet(const std::filesystem::path& base, const std::string& format) {
  if (base.has_parent_path()) std::filesystem::create_directories(base.parent_path());
  if (format == "h5" || format == "both") {
    paths_.push_back(std::filesystem::path(base.string() + ".h5"));
    sinks_.push_back(std::make_unique<io::Hdf5Writer>(paths_.back()));
  }
  if (format == "out" || format == "both") {
    paths_.push_back(std::filesystem::path(base.string() + ".out"));
    sinks_.push_back(std::make_unique<io::TextOutWriter>(paths_.back()));
  }
}

void OutputSet::begin(const std::vector<ChannelInfo>& channels, const io::RunMetadata& metadata) {
  for (auto& sink : sinks_) sink->begin(channels, metadata);
}

void OutputSet::append(double time_s, std::span<const double> values) {
  for (auto& sink : sinks_) sink->append(time_s, values);
}

void OutputSet::finish(const io::RunEnd& end) {
  for (auto& sink : sinks_) sink->finish(end);
}

}  // namespace fowtsim::driver
