#pragma once
// Deck values that pass the schema but are almost certainly a unit slip (a hub height of 90 km, an
// air density of 1225 kg/m³): the run goes ahead, its summary and outputs say so. Values no
// physics allows stay hard errors in the schemas and the scenes' rules.
#include <string>
#include <vector>

#include "fowtsim/io/schema.hpp"

namespace fowtsim::driver {

// One line per implausible value present in the deck, naming where it is written, the value and
// the range of sense. Sections the deck's scene does not have are skipped.
std::vector<std::string> implausible_values(const io::ValidatedDeck& deck);

}  // namespace fowtsim::driver
