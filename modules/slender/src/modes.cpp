#include "fowtsim/slender/modes.hpp"

#include "fowtsim/core/error.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <string>

namespace fowtsim::slender {

Modes compute_modes(const Model& model, int count) {
  const auto n = model.mass.rows();
  const Eigen::Index kept = (count <= 0 || count > n) ? n : count;
  if (!model.mass.allFinite() || !model.stiffness.allFinite())
    throw InputError({"slender.modes", std::nullopt, "M, K", "check the strip data"}, "non-finite mass or stiffness");
  // Eigen's generalised solver returns ascending eigenvalues and Vᵀ M V = I (the slide's scaling).
  Eigen::GeneralizedSelfAdjointEigenSolver<MatX> solver(model.stiffness, model.mass);
  if (solver.info() != Eigen::Success)
    throw InputError({"slender.modes", std::nullopt, "M", "every shape needs some mass"},
                     "the generalised eigenproblem failed (M not positive definite)");
  const VecX omega2 = solver.eigenvalues();
  const double scale = std::max(omega2.cwiseAbs().maxCoeff(), 1e-300);
  if (omega2(0) < -1e-10 * scale)
    throw InputError({"slender.modes", std::nullopt, "effective tension", "raise the top tension or stiffen the body"},
                     "K − ω²M has ω² = " + std::to_string(omega2(0)) + " rad²/s² < 0: the body buckles");
  return {omega2.head(kept).cwiseMax(0.0).cwiseSqrt(), solver.eigenvectors().leftCols(kept)};
}

}  // namespace fowtsim::slender
