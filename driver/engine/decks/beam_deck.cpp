#include "decks/beam_deck.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include <fmt/format.h>

#include "beamdyn/beamdyn_setup.hpp"
#include "decks/deck_helpers.hpp"
#include "decks/deck_section.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

using io::Schema;

namespace {

// Each key once: name, schema and the field it fills (decks/deck_section.hpp).
const DeckSection<BeamDefinitionKeys>& definition_section() {
  static const DeckSection<BeamDefinitionKeys> section = [] {
    DeckSection<beam::Station> station;
    station.key("eta", Schema::number().at_least(0.0).at_most(1.0).doc("arclength fraction from root (0) to tip (1)"),
                &beam::Station::eta)
        .key("stiffness", Schema::sequence(Schema::number()).min_items(36).max_items(36)
                              .doc("6×6 sectional stiffness, row by row, BeamDyn order (shear 1, shear 2, axial, "
                                   "bending 1, bending 2, torsion; axis 3 along the beam) [N, N·m, N·m²]"),
             &beam::Station::stiffness)
        .key("mass", Schema::sequence(Schema::number()).min_items(36).max_items(36)
                         .doc("6×6 sectional mass per length about the reference line, row by row, BeamDyn order "
                              "[kg/m, kg, kg·m]"),
             &beam::Station::mass);
    DeckSection<BeamDefinitionKeys> b;
    b.custom("beamdyn_file", Schema::string().optional()
                                 .doc("a BeamDyn primary input file (relative to this deck): its key points, twist and element "
                                      "order, and the blade file it names (stations, damping), instead of the four keys below"),
             [](const io::ValidatedDeck& d, const std::string& key, BeamDefinitionKeys& k) { k.beamdyn_file = file_beside_deck(d, key); })
        .key("key_points_m", Schema::sequence(number_vector(3, "x, y, z")).min_items(2).optional()
                                 .doc("reference line through these points, root first, z increasing"),
             &BeamDefinitionKeys::key_points_m)
        .key("twist_deg", Schema::sequence(Schema::number()).min_items(2).optional().doc("structural twist at each key point (BeamDyn sign)"),
             &BeamDefinitionKeys::twist_deg)
        .key("fit_degree", Schema::integer().at_least(1).at_most(20).default_value(5)
                               .doc("degree of the least-squares polynomial through the key points (BeamDyn's order_elem)"),
             &BeamDefinitionKeys::fit_degree)
        .list("stations", station, &BeamDefinitionKeys::stations, 1, "sectional properties, eta ascending")
        .key("damping_mu_s", number_vector(6, "stiffness-proportional damping per component (BeamDyn mu; "
                                              "overrides a BeamDyn file's)").optional(),
             &BeamDefinitionKeys::damping_mu_s)
        .key("mass_damping_1_s", Schema::number().unit("1_s").at_least(0.0).default_value(0.0).doc("mass-proportional damping μ_M"),
             &BeamDefinitionKeys::mass_damping_1_s);
    return b;
  }();
  return section;
}

}  // namespace

DeckSection<BeamKeys> beam_section(int default_segments, int max_segments) {
  DeckSection<BeamKeys> b;
  b.key("segments", Schema::integer().at_least(1).at_most(max_segments).default_value(default_segments).doc("finite volumes"),
        &BeamKeys::segments)
      .key("integrator", Schema::choice({"generalized_alpha", "erk"}).default_value("generalized_alpha")
                             .doc("integrator of the locally linear system in each step"),
           &BeamKeys::integrator)
      .key("spectral_radius", Schema::number().at_least(0.0).at_most(1.0).default_value(0.0)
                                  .doc("generalized-α ρ∞ (0: most high-frequency dissipation)"),
           &BeamKeys::spectral_radius)
      .keys_of(definition_section());
  return b;
}

namespace {

// The keys a BeamDyn file replaces, and whether the deck gives each.
std::array<std::pair<const char*, bool>, 3> own_keys(const BeamDefinitionKeys& keys) {
  return {{{"key_points_m", keys.key_points_m.has_value()},
           {"twist_deg", keys.twist_deg.has_value()},
           {"stations", keys.stations.has_value()}}};
}

// The beam of a BeamDyn primary file named by the deck; errors name the BeamDyn file and key, and
// the deck key that named it.
beam::BeamDefinition beamdyn_file_definition(const io::ValidatedDeck& deck, const std::string& path,
                                             const BeamDefinitionKeys& keys) {
  for (const auto& [key, given] : own_keys(keys))
    if (given)
      throw InputError({"beam", std::nullopt, path + "." + key, "beamdyn_file or the beam's own keys, not both"},
                       where(deck, path + "." + key) + ": the beam comes from beamdyn_file; remove " + key);
  try {
    const io::BeamDynPrimary primary = io::read_beamdyn_primary(*keys.beamdyn_file);
    return beamdyn_definition(primary, io::read_beamdyn_blade(primary.blade_file));
  } catch (const InputError& e) {
    throw InputError(e.context(), where(deck, path + ".beamdyn_file") + ": " + e.message());
  }
}

// The reference line and stations of the beam's own keys.
beam::BeamDefinition own_definition(const io::ValidatedDeck& deck, const std::string& path, const BeamDefinitionKeys& keys) {
  for (const auto& [key, given] : own_keys(keys))
    if (!given)
      throw InputError({"beam", std::nullopt, path + "." + key, "the beam's key points, twist and stations, or beamdyn_file"},
                       where(deck, path) + ": missing " + key + " (or give beamdyn_file: a BeamDyn primary input file)");
  const std::vector<Vec3>& points = *keys.key_points_m;
  const std::vector<double>& twist = *keys.twist_deg;
  if (twist.size() != points.size())
    throw InputError({"beam", std::nullopt, path + ".twist_deg", "one twist per key point"},
                     where(deck, path + ".twist_deg") + fmt::format(": expected one twist per key point ({}), found {}", points.size(), twist.size()));
  const int degree = std::min(keys.fit_degree, static_cast<int>(points.size()) - 1);
  beam::ReferenceLine line = [&] {
    try {
      return beamdyn_reference_line(points, twist, degree);
    } catch (const InputError& e) {
      throw InputError(e.context(), where(deck, path + ".key_points_m") + ": " + e.message());
    }
  }();
  beam::BeamDefinition definition{std::move(line), {}};
  double last_eta = -1.0;
  for (std::size_t i = 0; i < keys.stations->size(); ++i) {
    const double eta = (*keys.stations)[i].eta;
    if (!(eta > last_eta))
      throw InputError({"beam", std::nullopt, "eta", ""}, where(deck, path + fmt::format(".stations[{}].eta", i)) + ": eta must increase");
    last_eta = eta;
    definition.stations.push_back((*keys.stations)[i]);
  }
  return definition;
}

}  // namespace

beam::BeamDefinition beam_definition(const io::ValidatedDeck& deck, const std::string& path, const BeamDefinitionKeys& keys) {
  beam::BeamDefinition definition =
      keys.beamdyn_file ? beamdyn_file_definition(deck, path, keys) : own_definition(deck, path, keys);
  if (keys.damping_mu_s) definition.stiffness_damping = *keys.damping_mu_s;
  definition.mass_damping_1_s = keys.mass_damping_1_s;
  // The beam module's own checks (finite properties, mass per length and damping ≥ 0) now, at the
  // key the value came from ("beam.stations[2].mass", else the beam's section), rather than when the
  // beam is discretised with no location. A BeamDyn file's stations were checked as it was read.
  try {
    beam::validate(definition);
  } catch (const InputError& e) {
    const std::string key = path + "." + e.context().variable;
    throw InputError(e.context(), where(deck, deck.has(key) ? key : path) + ": " + e.message());
  }
  return definition;
}

beam::BeamDefinition beam_definition(const io::ValidatedDeck& deck, const std::string& path) {
  BeamDefinitionKeys keys;
  definition_section().read_into(deck.section(path), keys);
  return beam_definition(deck, path, keys);
}

}  // namespace fowtsim::driver
