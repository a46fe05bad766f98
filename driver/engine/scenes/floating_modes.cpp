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

}  // namespace

std::vector<std::string> coordinate_names(const std::vector<int>& dofs, int fore_aft) {
  std::vector<std::string> names;
  for (const int k : dofs) {
    if (k < multibody::kTower) names.push_back(kCoordinates[k]);
    else if (k < multibody::kBlade) {
      const int j = k - multibody::kTower;
      names.push_back(j < fore_aft ? fmt::format("TwFADOF{}", j + 1) : fmt::format("TwSSDOF{}", j + 1 - fore_aft));
    } else {
      const int j = k - multibody::kBlade;
      static const char* const mode[] = {"F1", "F2", "E1"};
      names.push_back(fmt::format("Q_B{}{}", j / multibody::kMaxBladeModes + 1, mode[j % multibody::kMaxBladeModes]));
    }
  }
  return names;
}

namespace {

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
  FloatingState state = scene.make_state();
  scene.settle_elastic(0.0, state);  // about the tower's and blades' static deflection
  const Eigen::MatrixXd a = scene.linearised_system(0.0, state);
  const std::vector<int> dofs = scene.coordinates();
  const int n = static_cast<int>(dofs.size());
  Eigen::EigenSolver<Eigen::MatrixXd> solver(a);
  if (solver.info() != Eigen::Success)
    throw NumericalError({"modes", 0.0, "eigenvalues", "check that the deck's structure is stable at its initial state"},
                         "the eigenvalue solver did not converge");
  ModesResult result;
  result.coordinates = coordinate_names(dofs, scene.tower_fore_aft_modes());
  const Eigen::VectorXcd lambda = solver.eigenvalues();
  // A free rotor's azimuth is a rigid-body (zero) mode; its eigenvalues come out as ±1e-8 rad/s of
  // round-off in the central differences, whose sign would read as a damping of ±1. Below 1e-6 of
  // the largest |λ| (the differences resolve ~1e-8 of it) an eigenvalue is zero.
  const double resolution = 1e-6 * lambda.cwiseAbs().maxCoeff();
  // One mode per conjugate pair (the one with Im λ ≥ 0) and per real eigenvalue.
  for (Eigen::Index i = 0; i < lambda.size(); ++i) {
    if (lambda[i].imag() < 0.0) continue;
    const std::complex<double> value = std::abs(lambda[i]) < resolution ? std::complex<double>(0.0) : lambda[i];
    result.modes.push_back(mode_of(value, solver.eigenvectors().col(i), n, result.coordinates));
  }
  std::sort(result.modes.begin(), result.modes.end(),
            [](const StructuralMode& x, const StructuralMode& y) { return x.frequency_hz < y.frequency_hz; });
  return result;
}

}  // namespace fowtsim::driver
