#include "fowtsim/beam/modal.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "fowtsim/beam/linear_system.hpp"

namespace fowtsim::beam {

std::vector<double> natural_frequencies_hz(const BeamModel& model, const BeamInput& input,
                                           const BeamState& state, int count) {
  LinearizedBeam sys;
  linearize(model, input, state, Inertia::included, sys);
  const int dofs = model.dof_count();
  const MatX k = sys.stiffness.dense();
  MatX minv_k(dofs, dofs);
  for (int n = 0; n < model.node_count(); ++n)
    minv_k.middleRows(6 * n, 6) = sys.mass[n].partialPivLu().solve(k.middleRows(6 * n, 6));
  const Eigen::EigenSolver<MatX> eig(minv_k, false);
  std::vector<double> f;
  for (int i = 0; i < dofs; ++i) {
    const double lambda = eig.eigenvalues()[i].real();  // ω²
    if (lambda > 0.0) f.push_back(std::sqrt(lambda) / (2.0 * 3.14159265358979323846));
  }
  std::sort(f.begin(), f.end());
  if (static_cast<int>(f.size()) > count) f.resize(count);
  return f;
}

}  // namespace fowtsim::beam
