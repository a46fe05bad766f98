#pragma once
// Private helpers of the deck loader shared with deck_settings.cpp: the merge of DESIGN.md §5 and
// the conversion of one YAML value given as text.
#include <string>

#include "fowtsim/io/deck.hpp"

namespace fowtsim::io::detail {

// Deep merge of DESIGN.md §5: keys of `over` replace those of `base`, except that two mappings
// under the same key merge recursively. Both arguments are mappings.
void merge_into(DeckNode& base, DeckNode over);

// `text` parsed as one YAML value (a scalar, or a flow sequence or mapping) placed at key path
// `path`, its nodes located at `origin`. Throws DeckError (yaml_syntax) if it is not YAML.
DeckNode parse_yaml_value(const std::string& text, const std::string& origin, const std::string& path);

}  // namespace fowtsim::io::detail
