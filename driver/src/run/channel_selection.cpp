#include "run/channel_selection.hpp"

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

std::vector<std::size_t> select_channels(const io::ValidatedDeck& deck, const std::vector<ChannelInfo>& all,
                                         const std::string& scene) {
  ChannelRegistry registry;
  for (const ChannelInfo& c : all) registry.add(c);
  std::vector<std::size_t> picked;
  if (!deck.has("output.channels")) {
    for (std::size_t i = 0; i < all.size(); ++i) picked.push_back(i);
    return picked;
  }
  const std::vector<std::string> names = deck.strings("output.channels");
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto index = registry.find(names[i]);
    if (!index) {
      std::string known;
      for (const ChannelInfo& c : all) known += (known.empty() ? "" : ", ") + c.name;
      throw InputError({scene, {}, names[i], "available: " + known},
                       where(deck, fmt::format("output.channels[{}]", i)) + ": unknown channel '" + names[i] + "'");
    }
    picked.push_back(*index);
  }
  return picked;
}

}  // namespace fowtsim::driver
