// Reading the per-channel tolerance file of `fowtsim compare --tolerances`.
#include "compare/channel_compare.hpp"
#include "fowtsim/io/schema.hpp"

namespace fowtsim::driver {
namespace {

io::Schema tolerance_schema() {
  using io::Schema;
  // rtol is dimensionless; atol is in the channel's own unit, so it carries no key suffix.
  return Schema::map({
      {"rtol", Schema::number().at_least(0.0).default_value(1e-6).doc("relative tolerance")},
      {"atol", Schema::number().at_least(0.0).default_value(1e-9).doc("absolute tolerance, channel unit")},
      {"range_atol", Schema::number().at_least(0.0).default_value(0.0).doc("absolute tolerance per unit of the channel's range")},
  });
}

io::Schema tolerance_file_schema() {
  using io::Schema;
  return Schema::map({
      {"default", tolerance_schema().optional().doc("tolerance of channels not listed")},
      {"channels", Schema::map_of(tolerance_schema()).optional().doc("per-channel tolerances; listed = required")},
      {"aliases", Schema::map_of(Schema::string()).optional().doc("a channel's name in the other file (FAIRTEN1: T[1])")},
  });
}

ChannelTolerance read_tolerance(const io::ValidatedDeck& deck) {
  return {deck.number("rtol"), deck.number("atol"), deck.number("range_atol")};
}

}  // namespace

CompareOptions load_tolerance_file(const std::string& path) {
  const io::ValidatedDeck deck = io::read_deck(tolerance_file_schema(), path);
  CompareOptions options;
  if (deck.has("default")) options.default_tolerance = read_tolerance(deck.section("default"));
  if (deck.has("channels")) {
    const io::ValidatedDeck channels = deck.section("channels");
    for (const std::string& name : channels.keys("")) {
      options.tolerances[name] = read_tolerance(channels.section(name));
      options.channels.push_back(name);
    }
  }
  if (deck.has("aliases")) {
    const io::ValidatedDeck aliases = deck.section("aliases");
    for (const std::string& name : aliases.keys("")) options.aliases[name] = aliases.string(name);
  }
  return options;
}

}  // namespace fowtsim::driver
