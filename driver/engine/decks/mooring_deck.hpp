#pragma once
// The `mooring:` deck section ↔ mooring::MooringParams, key for key (modules/mooring/params.hpp).
#include "fowtsim/core/interface.hpp"
#include "fowtsim/io/schema.hpp"
#include "fowtsim/mooring/params.hpp"

namespace fowtsim::driver {

io::Schema mooring_schema();
mooring::MooringParams mooring_params(const io::ValidatedDeck& section);

// Cross-key checks of the mooring against the platform's initial pose (`deck`: the scene deck):
// the reference point above the seabed, and no line stretched beyond what any line material
// survives. Refused at the initial position's deck line (else the line's), as an input error
// rather than a catenary that fails at t = 0.
void check_mooring_at_initial_pose(const io::ValidatedDeck& deck, const mooring::MooringParams& mooring,
                                   const FrameMotion& initial_pose);

}  // namespace fowtsim::driver
