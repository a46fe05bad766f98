// Proper orthogonal modes of a synthetic field made of two known modes.
#include <cmath>
#include <numbers>

#include <catch2/catch.hpp>

#include "fowtsim/post/proper_orthogonal_modes.hpp"

using namespace fowtsim::post;

namespace {

constexpr int samples = 2000, nodes = 20;

// Two orthonormal shapes along a blade (Gram–Schmidt of a flap-like and a twist-like curve).
std::pair<Eigen::VectorXd, Eigen::VectorXd> two_shapes() {
  Eigen::VectorXd first(nodes), second(nodes);
  for (int i = 0; i < nodes; ++i) {
    const double x = (i + 1.0) / nodes;
    first(i) = x * x;
    second(i) = std::sin(2.0 * std::numbers::pi * x);
  }
  first.normalize();
  second -= second.dot(first) * first;
  second.normalize();
  return {first, second};
}

// Unit time histories that are exactly orthogonal over the record: sines of 5 and 17 whole periods.
Eigen::VectorXd unit_history(int periods) {
  Eigen::VectorXd a(samples);
  for (int j = 0; j < samples; ++j) a(j) = std::sin(2.0 * std::numbers::pi * periods * j / samples);
  return a.normalized();
}

}  // namespace

TEST_CASE("POMs of a field of two orthogonal modes return the modes and their ratios", "[verification]") {
  // X = 3 a₁ φ₁ᵀ + 1 a₂ φ₂ᵀ with orthonormal a, φ is its own SVD: σ = (3, 1), ratios σᵢ/Σσ = 0.75 and
  // 0.25 (seed 000 §4.6.4 definition), energy 0.9 and 0.1, shapes φ₁, φ₂. Tolerances: round-off of
  // a 2000×20 SVD, 10× the measured: σ and ratios ≤ 1.7e-15 relative → 2e-14, the null singular
  // values ≤ 5.3e-15 → 5e-14, shapes, amplitudes and the rebuilt field ≤ 1.5e-15 → 2e-14.
  const auto [phi1, phi2] = two_shapes();
  const Eigen::VectorXd a1 = unit_history(5), a2 = unit_history(17);
  const Eigen::MatrixXd field = 3.0 * a1 * phi1.transpose() + 1.0 * a2 * phi2.transpose();
  const ProperOrthogonalModes modes = proper_orthogonal_modes(field);
  REQUIRE(modes.singular_values.size() == nodes);
  CHECK(modes.singular_values(0) == Approx(3.0).epsilon(2e-14));
  CHECK(modes.singular_values(1) == Approx(1.0).epsilon(2e-14));
  CHECK(modes.singular_values(2) < 5e-14);
  CHECK(modes.singular_value_ratios(0) == Approx(0.75).epsilon(2e-14));
  CHECK(modes.singular_value_ratios(1) == Approx(0.25).epsilon(2e-14));
  CHECK(modes.energy_fractions(0) == Approx(0.9).epsilon(2e-14));
  // Shapes up to the sign rule (largest component positive: both φ here have it positive or are flipped).
  const double sign1 = phi1.cwiseAbs().maxCoeff() == phi1.maxCoeff() ? 1.0 : -1.0;
  const double sign2 = phi2.cwiseAbs().maxCoeff() == phi2.maxCoeff() ? 1.0 : -1.0;
  CHECK((modes.shapes.col(0) - sign1 * phi1).cwiseAbs().maxCoeff() < 2e-14);
  CHECK((modes.shapes.col(1) - sign2 * phi2).cwiseAbs().maxCoeff() < 2e-14);
  // Modal amplitudes are σᵢ aᵢ(t) in deflection units, and rebuild the field.
  CHECK((modes.modal_amplitudes.col(0) - sign1 * 3.0 * a1).cwiseAbs().maxCoeff() < 2e-14);
  const Eigen::MatrixXd rebuilt = modes.modal_amplitudes * modes.shapes.transpose();
  CHECK((rebuilt - field).cwiseAbs().maxCoeff() < 2e-14);
}

TEST_CASE("POMs with node means removed see only the fluctuation", "[unit]") {
  // A static deflection added to the two-mode field is the whole first mode when kept (the seed's
  // decomposition) and disappears when node means are removed.
  const auto [phi1, phi2] = two_shapes();
  const Eigen::MatrixXd fluctuation = 3.0 * unit_history(5) * phi1.transpose() + unit_history(17) * phi2.transpose();
  Eigen::VectorXd static_shape = Eigen::VectorXd::LinSpaced(nodes, 0.1, 2.0);
  const Eigen::MatrixXd field = fluctuation.rowwise() + static_shape.transpose();
  const ProperOrthogonalModes kept = proper_orthogonal_modes(field);
  CHECK(kept.singular_values(0) > 10.0 * 3.0);  // the mean shape, √2000 · |static| ≈ 240
  const ProperOrthogonalModes removed = proper_orthogonal_modes(field, true);
  // Round-off as above (measured 1.3e-15 on the means, ≤ 5.6e-16 on σ); 2e-14.
  CHECK((removed.node_means - static_shape).cwiseAbs().maxCoeff() < 2e-14);  // sines of whole periods have zero mean
  CHECK(removed.singular_values(0) == Approx(3.0).epsilon(2e-14));
  CHECK(removed.singular_values(1) == Approx(1.0).epsilon(2e-14));
}
