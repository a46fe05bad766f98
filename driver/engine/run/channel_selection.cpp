#include "run/channel_selection.hpp"

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "scenes/scene_runner.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/io/suggest.hpp"

namespace fowtsim::driver {

std::vector<std::size_t> select_channels(const io::ValidatedDeck& deck, const std::vector<ChannelInfo>& all,
                                         const std::string& scene) {
  ChannelRegistry registry;
  for (const ChannelInfo& c : all) registry.add(c);
  std::vector<std::size_t> picked;
  const std::optional<std::vector<std::string>> listed = output_keys(deck).channels;
  if (!listed) {
    for (std::size_t i = 0; i < all.size(); ++i) picked.push_back(i);
    return picked;
  }
  const std::vector<std::string>& names = *listed;
  std::vector<std::string> known;
  std::string known_text;
  for (const ChannelInfo& c : all) {
    known.push_back(c.name);
    known_text += (known_text.empty() ? "" : ", ") + c.name;
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto index = registry.find(names[i]);
    if (!index) {
      const std::string suggestion = io::did_you_mean(names[i], known, io::LetterCase::ignored);
      const std::string hint = suggestion.empty() ? "available: " + known_text
                                                  : suggestion + " (available: " + known_text + ")";
      throw InputError({scene, {}, names[i], hint}, where(deck, fmt::format("output.channels[{}]", i)) +
                                                        ": unknown channel '" + names[i] + "'" +
                                                        (suggestion.empty() ? "" : "; " + suggestion));
    }
    picked.push_back(*index);
  }
  return picked;
}

}  // namespace fowtsim::driver
