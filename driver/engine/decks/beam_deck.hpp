#pragma once
// The beam definition of a deck — reference line through key points (BeamDyn's polynomial fit),
// structural twist, sectional 6×6 stiffness and mass, damping — shared by the one-beam scene
// (`beam:`) and the flexible blades of the floating turbine (`blades:`).
#include <string>
#include <vector>

#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/io/schema.hpp"

namespace fowtsim::driver {

// segments, integrator, spectral_radius, key_points_m, twist_deg, fit_degree, stations,
// damping_mu_s, mass_damping_1_s.
std::vector<io::SchemaField> beam_schema_fields(int default_segments, int max_segments);

// The definition in the section at `path` of `deck` (errors located at its keys).
beam::BeamDefinition beam_definition(const io::ValidatedDeck& deck, const std::string& path);

}  // namespace fowtsim::driver
