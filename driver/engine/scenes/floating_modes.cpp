#include "scenes/floating_modes.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/deck.hpp"
#include "scenes/floating_scene.hpp"

namespace fowtsim::driver {
namespace {

const char* const kCoordinates[] = {"PtfmSurge", "PtfmSway", "PtfmHeave", "PtfmRoll", "PtfmPitch", "PtfmYaw", "Azimuth",
                                    "GenAzimuth"};

// A mode from one eigenpair: its shape (displacements) rotated so that its largest entry is real and
// positive, then scaled to 1.
StructuralMode mode_of(const std::complex<double>& lambda, const Eigen::VectorXcd& vector, int n) {
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
  m.dominant = kCoordinates[largest];
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
  result.coordinates.assign(kCoordinates, kCoordinates + n);
  const Eigen::VectorXcd lambda = solver.eigenvalues();
  // One mode per conjugate pair (the one with Im λ ≥ 0) and per real eigenvalue.
  for (Eigen::Index i = 0; i < lambda.size(); ++i) {
    if (lambda[i].imag() < 0.0) continue;
    result.modes.push_back(mode_of(lambda[i], solver.eigenvectors().col(i), n));
  }
  std::sort(result.modes.begin(), result.modes.end(),
            [](const StructuralMode& x, const StructuralMode& y) { return x.frequency_hz < y.frequency_hz; });
  return result;
}

}  // namespace fowtsim::driver
