#pragma once
// Output channel registry: every channel a module can write is declared once with its
// OpenFAST-style name, unit and description, before the run starts (DESIGN.md §3, §6).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace fowtsim {

struct ChannelInfo {
  std::string name;         // OpenFAST-style channel name, e.g. "PtfmSurge"; unique in a run
  std::string unit;         // unit as written in outputs, e.g. "m", "deg", "kN", "-"
  std::string description;  // one line: meaning, frame and sign convention
  std::string module;       // module that produces it, e.g. "toy"
};

class ChannelRegistry {
 public:
  // Adds a channel and returns its column index. Throws InputError on a duplicate name or an
  // invalid name (empty, whitespace, longer than 64 characters).
  std::size_t add(ChannelInfo info);

  std::optional<std::size_t> find(const std::string& name) const;
  const ChannelInfo& at(std::size_t index) const { return channels_.at(index); }
  std::size_t size() const { return channels_.size(); }
  const std::vector<ChannelInfo>& all() const { return channels_; }

 private:
  std::vector<ChannelInfo> channels_;
};

}  // namespace fowtsim
