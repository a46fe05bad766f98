#pragma once
// OpenFAST's channel names against ours (issue 23): the names that differ with the same meaning
// (MAP++'s T[1] is our FAIRTEN1) and, for a name we do not write, why — an alias, an OpenFAST
// channel fowtsim does not compute (with the reason), or a misspelling. Used by the deck's
// `output.channels` and by `fowtsim compare`.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fowtsim::driver {

// A channel OpenFAST writes under another name than ours, with the same definition and possibly
// another unit (the comparison converts units separately).
struct ChannelAlias {
  std::string openfast;  // e.g. "T[1]"
  std::string ours;      // e.g. "FAIRTEN1"
  std::string source;    // who writes the OpenFAST name and what it is, e.g. "MAP++'s fairlead tension of line 1"
};

// The built-in alias of `name`, given either its OpenFAST name or ours (case-insensitive).
std::optional<ChannelAlias> builtin_alias(std::string_view name);

// Why `name` is not among `available` (the channels of a scene or a file), as one phrase:
// "MAP++'s name for FAIRTEN1 …: did you mean `FAIRTEN1`?", "tower-top deflection: needs a flexible
// tower …", "did you mean `RotSpeed`?", or "" when nothing is known about it.
std::string why_missing(const std::string& name, const std::vector<std::string>& available);

}  // namespace fowtsim::driver
