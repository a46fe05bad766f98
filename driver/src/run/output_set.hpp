#pragma once
// The output files of one run (HDF5 and/or OpenFAST text), fed together.
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "fowtsim/io/output_sink.hpp"

namespace fowtsim::driver {

class OutputSet {
 public:
  // format: "h5", "out" or "both"; files are base + ".h5" / ".out"; the directory is created.
  OutputSet(const std::filesystem::path& base, const std::string& format);

  void begin(const std::vector<ChannelInfo>& channels, const io::RunMetadata& metadata);
  void append(double time_s, std::span<const double> values);
  void finish(const io::RunEnd& end);
  const std::vector<std::filesystem::path>& paths() const { return paths_; }

 private:
  std::vector<std::unique_ptr<io::OutputSink>> sinks_;
  std::vector<std::filesystem::path> paths_;
};

}  // namespace fowtsim::driver
