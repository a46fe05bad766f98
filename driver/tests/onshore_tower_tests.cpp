// The land-based NREL 5MW tower of inputs/nrel5mw/onshore_structure.yaml (38060's properties,
// OpenFAST's land-based ElastoDyn mode shapes): ElastoDyn's per-mode side-side frequencies, each
// shape alone as a Rayleigh quotient on its 20 tower nodes (midpoint rule), as welib's test of
// ElastoDyn's tower parameters computes them (fast/tests/test_elastodyn.py, FreqTSS): 0.931115438 /
// 3.080181973 Hz alone; with the 347,107 kg top mass (TwrTpMass at AdjBlMs = 1) and gravity the
// issue quotes 0.3351 / 3.0562 Hz.
#include <cmath>
#include <numbers>

#include <catch2/catch.hpp>

#include "decks/structure_deck.hpp"
#include "fowtsim/core/interpolation.hpp"
#include "fowtsim/flexbody/axial_force.hpp"
#include "fowtsim/flexbody/integrals.hpp"
#include "fowtsim/flexbody/shape_functions.hpp"
#include "fowtsim/io/deck.hpp"
#include "fowtsim/testing/skip.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

TEST_CASE("the land-based tower deck gives ElastoDyn's per-mode tower frequencies", "[verification][flexible_tower]") {
  const io::ValidatedDeck deck =
      io::read_deck(io::Schema::map({{"structure", structure_schema()}}), testing::source_dir() / "inputs/nrel5mw/onshore_structure.yaml");
  const multibody::Params p = structure_params(deck.section("structure"));
  const multibody::TowerParams& t = p.tower;
  const double length = t.top_height_m - t.base_height_m;
  flexbody::BeamStations table;
  for (std::size_t i = 0; i < t.station_fraction.size(); ++i) {
    table.x.push_back(t.station_fraction[i] * length);
    table.m.push_back(t.mass_density_kg_m[i]);
    table.EI.push_back(t.side_side_stiffness_N_m2[i]);
  }
  // ElastoDyn's 20 tower nodes: element midpoints, properties interpolated there.
  constexpr int kNodes = 20;
  std::vector<flexbody::QuadraturePoint> nodes;
  const double h = length / kNodes;
  for (int j = 0; j < kNodes; ++j) {
    const double x = (j + 0.5) * h;
    nodes.push_back({x, h, interpolate_linear(table.x, table.m, x), interpolate_linear(table.x, table.EI, x)});
  }
  const double top_mass = 347107.0092772355, g = 9.80665;
  const double expected_alone[] = {0.931115438458394, 3.080181973131150};
  const double expected_loaded[] = {0.3351, 3.0562};
  for (int mode = 0; mode < 2; ++mode) {
    const auto& c = t.side_side_mode_shapes[static_cast<std::size_t>(mode)];
    const flexbody::SampledBody body = flexbody::sample(nodes, {flexbody::polynomial_shape({c[0], c[1], c[2], c[3], c[4]}, length)});
    const double m = flexbody::generalized_mass(body)(0, 0), k = flexbody::generalized_stiffness(body)(0, 0);
    const flexbody::AxialForce self = flexbody::self_weight_axial_force(table, g), top = flexbody::top_mass_axial_force(top_mass, g);
    const double k_gravity = flexbody::geometric_stiffness(body, [&](double x) { return self(x) + top(x); })(0, 0);
    const double alone = std::sqrt(k / m) / (2.0 * std::numbers::pi);
    const double loaded = std::sqrt((k + k_gravity) / (m + top_mass)) / (2.0 * std::numbers::pi);
    WARN("side-side mode " << mode + 1 << ": alone " << alone << " Hz, with top mass and gravity " << loaded << " Hz");
    // Alone: the same rule on the same data; mode 1 measured 6e-7: 1e-5. Mode 2's coefficients are
    // known to 3 decimals here and the last was raised by 0.001 to sum to 1 (the deck's header):
    // measured 3.5e-5: 2e-4.
    CHECK(alone == Approx(expected_alone[mode]).epsilon(mode == 0 ? 1e-5 : 2e-4));
    // Loaded: the quote's 4 digits (±1.5e-4 of rounding) and a self-weight axial force integrated
    // exactly here where ElastoDyn sums its nodes: measured 1.8e-4 (mode 1) and 3.6e-5 (mode 2): 1e-3.
    CHECK(loaded == Approx(expected_loaded[mode]).epsilon(1e-3));
  }
}
