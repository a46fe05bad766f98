#pragma once
// The beam definition of a deck — reference line through key points (BeamDyn's polynomial fit),
// structural twist, sectional 6×6 stiffness and mass, damping — shared by the one-beam scene
// (`beam:`) and the flexible blades of the floating turbine (`blades:`).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "decks/deck_section.hpp"
#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/io/schema.hpp"

namespace fowtsim::driver {

// The keys of the beam definition as written; beam_definition checks them against one another
// (beamdyn_file or the beam's own keys, one twist per key point, eta increasing) and builds it.
struct BeamDefinitionKeys {
  std::optional<std::filesystem::path> beamdyn_file;  // beside the deck file that names it
  std::optional<std::vector<Vec3>> key_points_m;
  std::optional<std::vector<double>> twist_deg;
  int fit_degree = 5;
  std::optional<std::vector<beam::Station>> stations;
  std::optional<Vec6> damping_mu_s;
  double mass_damping_1_s = 0.0;
};

// The beam keys: the definition's and how the beam is discretised and integrated.
struct BeamKeys : BeamDefinitionKeys {
  int segments = 0;
  std::string integrator;
  double spectral_radius = 0.0;
};

// segments, integrator, spectral_radius, beamdyn_file, key_points_m, twist_deg, fit_degree,
// stations, damping_mu_s, mass_damping_1_s.
DeckSection<BeamKeys> beam_section(int default_segments, int max_segments);

// The definition from its keys read from the section at `path` of `deck` (errors located at its keys).
beam::BeamDefinition beam_definition(const io::ValidatedDeck& deck, const std::string& path, const BeamDefinitionKeys& keys);
// The same, reading the keys.
beam::BeamDefinition beam_definition(const io::ValidatedDeck& deck, const std::string& path);

}  // namespace fowtsim::driver
