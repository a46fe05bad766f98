#include "run/channel_selection.hpp"

#include <fmt/format.h>

#include "decks/deck_helpers.hpp"
#include "run/channel_names.hpp"
#include "scenes/scene_runner.hpp"
#include "fowtsim/core/error.hpp"

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
  for (const ChannelInfo& c : all) known.push_back(c.name);
  const std::string available = fmt::format("available: {}", fmt::join(known, ", "));
  // Every unknown name at once, each with its reason, so one edit of the deck fixes them all.
  std::vector<std::string> problems, unknown;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (const auto index = registry.find(names[i])) {
      picked.push_back(*index);
      continue;
    }
    const std::string reason = why_missing(names[i], known);
    problems.push_back(fmt::format("  {}: unknown channel '{}': {}", where(deck, fmt::format("output.channels[{}]", i)),
                                   names[i], reason.empty() ? "not a channel of this scene" : reason));
    unknown.push_back(names[i]);
  }
  if (!problems.empty()) {
    throw InputError({scene, {}, fmt::format("{}", fmt::join(unknown, ", ")), available},
                     fmt::format("output.channels names {} channel{} this scene does not write:\n{}", problems.size(),
                                 problems.size() == 1 ? "" : "s", fmt::join(problems, "\n")));
  }
  return picked;
}

}  // namespace fowtsim::driver
