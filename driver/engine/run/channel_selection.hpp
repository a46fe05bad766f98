#pragma once
// The channels a scene writes: those its deck lists under `output.channels`, or all.
#include <string>
#include <vector>

#include "fowtsim/core/channels.hpp"
#include "fowtsim/io/schema.hpp"

namespace fowtsim::driver {

// Indices into `all` of the channels named in the deck's `output.channels` (in the deck's order),
// or of every channel when the deck names none. An unknown name throws InputError with its
// file:line and the names available; `scene` names the raising scene in the error context.
std::vector<std::size_t> select_channels(const io::ValidatedDeck& deck, const std::vector<ChannelInfo>& all,
                                         const std::string& scene);

}  // namespace fowtsim::driver
