#include "decks/beam_deck.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "beamdyn/beamdyn_setup.hpp"
#include "decks/deck_helpers.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::driver {

using io::Schema;

namespace {

Schema station_schema() {
  return Schema::map({
      {"eta", Schema::number().at_least(0.0).at_most(1.0).doc("arclength fraction from root (0) to tip (1)")},
      {"stiffness", Schema::sequence(Schema::number()).min_items(36).max_items(36)
                        .doc("6×6 sectional stiffness, row by row, BeamDyn order (shear 1, shear 2, axial, "
                             "bending 1, bending 2, torsion; axis 3 along the beam) [N, N·m, N·m²]")},
      {"mass", Schema::sequence(Schema::number()).min_items(36).max_items(36)
                   .doc("6×6 sectional mass per length about the reference line, row by row, BeamDyn order "
                        "[kg/m, kg, kg·m]")},
  });
}

}  // namespace

std::vector<io::SchemaField> beam_schema_fields(int default_segments, int max_segments) {
  return {
      {"segments", Schema::integer().at_least(1).at_most(max_segments).default_value(default_segments).doc("finite volumes")},
      {"integrator", Schema::choice({"generalized_alpha", "erk"}).default_value("generalized_alpha")
                         .doc("integrator of the locally linear system in each step")},
      {"spectral_radius", Schema::number().at_least(0.0).at_most(1.0).default_value(0.0)
                              .doc("generalized-α ρ∞ (0: most high-frequency dissipation)")},
      {"beamdyn_file", Schema::string().optional()
                           .doc("a BeamDyn primary input file (relative to this deck): its key points, twist and element "
                                "order, and the blade file it names (stations, damping), instead of the four keys below")},
      {"key_points_m", Schema::sequence(number_vector(3, "x, y, z")).min_items(2).optional()
                           .doc("reference line through these points, root first, z increasing")},
      {"twist_deg", Schema::sequence(Schema::number()).min_items(2).optional().doc("structural twist at each key point (BeamDyn sign)")},
      {"fit_degree", Schema::integer().at_least(1).at_most(20).default_value(5)
                         .doc("degree of the least-squares polynomial through the key points (BeamDyn's order_elem)")},
      {"stations", Schema::sequence(station_schema()).min_items(1).optional().doc("sectional properties, eta ascending")},
      {"damping_mu_s", number_vector(6, "stiffness-proportional damping per component (BeamDyn mu; "
                                        "overrides a BeamDyn file's)").optional()},
      {"mass_damping_1_s", Schema::number().unit("1_s").at_least(0.0).default_value(0.0).doc("mass-proportional damping μ_M")},
  };
}

namespace {

// The beam of a BeamDyn primary file named by the deck; errors name the BeamDyn file and key, and
// the deck key that named it.
beam::BeamDefinition beamdyn_file_definition(const io::ValidatedDeck& deck, const std::string& path) {
  const io::ValidatedDeck b = deck.section(path);
  for (const char* key : {"key_points_m", "twist_deg", "stations"})
    if (b.has(key))
      throw InputError({"beam", std::nullopt, path + "." + key, "beamdyn_file or the beam's own keys, not both"},
                       where(deck, path + "." + key) + ": the beam comes from beamdyn_file; remove " + key);
  const std::filesystem::path file = b.string("beamdyn_file");
  const std::filesystem::path resolved =
      file.is_absolute() ? file : std::filesystem::path(b.location("beamdyn_file").file).parent_path() / file;
  try {
    const io::BeamDynPrimary primary = io::read_beamdyn_primary(resolved);
    return beamdyn_definition(primary, io::read_beamdyn_blade(primary.blade_file));
  } catch (const InputError& e) {
    throw InputError(e.context(), where(deck, path + ".beamdyn_file") + ": " + e.message());
  }
}

}  // namespace

beam::BeamDefinition beam_definition(const io::ValidatedDeck& deck, const std::string& path) {
  const io::ValidatedDeck b = deck.section(path);
  if (b.has("beamdyn_file")) {
    beam::BeamDefinition definition = beamdyn_file_definition(deck, path);
    if (b.has("damping_mu_s")) {
      const auto mu = b.numbers("damping_mu_s");
      definition.stiffness_damping = Eigen::Map<const Vec6>(mu.data());
    }
    definition.mass_damping_1_s = b.number("mass_damping_1_s");
    return definition;
  }
  for (const char* key : {"key_points_m", "twist_deg", "stations"})
    if (!b.has(key))
      throw InputError({"beam", std::nullopt, path + "." + key, "the beam's key points, twist and stations, or beamdyn_file"},
                       where(deck, path) + ": missing " + key + " (or give beamdyn_file: a BeamDyn primary input file)");
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < b.size("key_points_m"); ++i) {
    const auto p = b.numbers(fmt::format("key_points_m[{}]", i));
    points.emplace_back(p[0], p[1], p[2]);
  }
  const std::vector<double> twist = b.numbers("twist_deg");
  if (twist.size() != points.size())
    throw InputError({"beam", std::nullopt, path + ".twist_deg", "one twist per key point"},
                     where(deck, path + ".twist_deg") + fmt::format(": expected one twist per key point ({}), found {}", points.size(), twist.size()));
  const int degree = std::min(static_cast<int>(b.integer("fit_degree")), static_cast<int>(points.size()) - 1);
  beam::ReferenceLine line = [&] {
    try {
      return beamdyn_reference_line(points, twist, degree);
    } catch (const InputError& e) {
      throw InputError(e.context(), where(deck, path + ".key_points_m") + ": " + e.message());
    }
  }();
  beam::BeamDefinition definition{std::move(line), {}};
  double last_eta = -1.0;
  for (std::size_t i = 0; i < b.size("stations"); ++i) {
    const io::ValidatedDeck st = b.section(fmt::format("stations[{}]", i));
    const double eta = st.number("eta");
    if (!(eta > last_eta))
      throw InputError({"beam", std::nullopt, "eta", ""}, where(deck, path + fmt::format(".stations[{}].eta", i)) + ": eta must increase");
    last_eta = eta;
    definition.stations.push_back({eta, mat6(st, "stiffness"), mat6(st, "mass")});
  }
  if (b.has("damping_mu_s")) {
    const auto mu = b.numbers("damping_mu_s");
    definition.stiffness_damping = Eigen::Map<const Vec6>(mu.data());
  }
  definition.mass_damping_1_s = b.number("mass_damping_1_s");
  return definition;
}

}  // namespace fowtsim::driver
