#pragma once
// The `hydro:` deck section ↔ hydro::Params, key for key (modules/hydro/README.md).
#include <optional>

#include "fowtsim/hydro/params.hpp"
#include "fowtsim/io/schema.hpp"
#include "fowtsim/io/wamit_input.hpp"

namespace fowtsim::driver {

io::Schema hydro_schema();

struct HydroDeck {
  hydro::Params params;
  std::optional<io::WamitExcitation> excitation;  // the .3 table, with potential-flow excitation
};

// Reads a validated `hydro:` section (WAMIT files named relative to the deck file that holds the
// key); `large_step_s` is the platform's step, the radiation memory's sample interval. A value the
// module rejects, or a WAMIT file that cannot be read, is reported with file:line.
HydroDeck read_hydro_deck(const io::ValidatedDeck& section, double large_step_s);

}  // namespace fowtsim::driver
