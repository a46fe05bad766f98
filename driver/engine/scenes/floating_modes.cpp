#include "scenes/floating_modes.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/deck.hpp"
#include "scenes/floating_scene.hpp"

namespace fowtsim::driver {
namespace {

const char* const kCoordinates[] = {"PtfmSurge", "PtfmSway", "PtfmHeave", "PtfmRoll", "PtfmPitch", "PtfmYaw", "Azimuth",
                                    "GenAzimuth"};

// The names of the model's coordinates: the above, then a flexible tower's modes, fore-aft first
// (ElastoDyn's DOF names TwFADOF1, TwFADOF2, TwSSDOF1, TwSSDOF2).
std::vector<std::string> coordinate_names(int n, int fore_aft) {
  std::vector<std::string> names(kCoordinates, kCoordinates + std::min(n, 8));
  for (int j = 8; j < n; ++j)
    names.push_back(j - 8 < fore_aft ? fmt::format("TwFADOF{}", j - 7) : fmt::format("TwSSDOF{}", j - 7 - fore_aft));
  return names;
}

// A mode from one eigenpair: its shape (displacements) rotated so that its largest entry is real and
// positive, then scaled to 1.
StructuralMode mode_of(const std::complex<double>& lambda, const Eigen::VectorXcd& vector, int n,
                       const std::vector<std::string>& names) {
  StructuralMode m;
  const double magnitude = std::abs(lambda);
  m.frequency_hz = magnitude / (2.0 * std::numbers::pi);
  m.damping_ratio = magnitude > 0.0 ? -lambda.real() / magnitude : 0.0;
  Eigen::VectorXcd q = vector.head(n);
  Eigen::Index largest = 0;
  q.cwiseAbs().maxCoeff(&largest);
  const std::complex<double> pivot = q[largest];
  if (std::abs(pivot) > 0.0) q /= pivot;
  m.shape = q.real();
  m.dominant = names[largest];
  return m;
}

}  // namespace

ModesResult floating_modes(const std::filesystem::path& deck_path, const std::vector<std::string>& settings) {
  const io::ValidatedDeck deck = io::read_deck(floating_scene_schema(), deck_path, settings);
  FloatingScene scene(deck);
  const FloatingState state = scene.make_state();
  const Eigen::MatrixXd a = scene.linearised_system(0.0, state);
  const int n = scene.dof_count();
  Eigen::EigenSolver<Eigen::MatrixXd> solver(a);
  if (solver.info() != Eigen::Success)
    throw NumericalError({"modes", 0.0, "eigenvalues", "check that the deck's structure is stable at its initial state"},
                         "the eigenvalue solver did not converge");
  ModesResult result;
  result.coordinates = coordinate_names(n, scene.tower_fore_aft_modes());
  const Eigen::VectorXcd lambda = solver.eigenvalues();
  // One mode per conjugate pair (the one with Im λ ≥ 0) and per real eigenvalue.
  for (Eigen::Index i = 0; i < lambda.size(); ++i) {
    if (lambda[i].imag() < 0.0) continue;
    result.modes.push_back(mode_of(lambda[i], solver.eigenvectors().col(i), n, result.coordinates));
  }
  std::sort(result.modes.begin(), result.modes.end(),
            [](const StructuralMode& x, const StructuralMode& y) { return x.frequency_hz < y.frequency_hz; });
  return result;
}

}  // namespace fowtsim::driver
