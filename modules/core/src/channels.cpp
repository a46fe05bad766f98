#include "fowtsim/core/channels.hpp"

#include <algorithm>
#include <cctype>

#include "fowtsim/core/error.hpp"

namespace fowtsim {

std::size_t ChannelRegistry::add(ChannelInfo info) {
  const bool bad_name =
      info.name.empty() || info.name.size() > 64 ||
      std::any_of(info.name.begin(), info.name.end(),
                  [](unsigned char c) { return std::isspace(c) || !std::isprint(c); });
  if (bad_name) {
    throw InputError({info.module, {}, info.name, "use letters, digits and _ only"},
                     "invalid output channel name '" + info.name + "'");
  }
  if (find(info.name)) {
    throw InputError({info.module, {}, info.name, "each channel name must be unique"},
                     "output channel '" + info.name + "' declared twice (first by module '" +
                         channels_[*find(info.name)].module + "')");
  }
  channels_.push_back(std::move(info));
  return channels_.size() - 1;
}

std::optional<std::size_t> ChannelRegistry::find(const std::string& name) const {
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    if (channels_[i].name == name) return i;
  }
  return std::nullopt;
}

}  // namespace fowtsim
