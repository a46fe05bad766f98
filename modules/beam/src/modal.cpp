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

std::vector<DampedMode> damped_modes(const BeamModel& model, const BeamInput& input, const BeamState& state) {
  LinearizedBeam sys;
  linearize(model, input, state, Inertia::included, sys);
  const int dofs = model.dof_count();
  const MatX k = sys.stiffness.dense(), c = sys.damping.dense();
  // [q̇; q̈] = [0 I; −M⁻¹K −M⁻¹C] [q; q̇], M block diagonal.
  MatX a = MatX::Zero(2 * dofs, 2 * dofs);
  a.topRightCorner(dofs, dofs).setIdentity();
  for (int n = 0; n < model.node_count(); ++n) {
    const auto lu = sys.mass[n].partialPivLu();
    a.block(dofs + 6 * n, 0, 6, dofs) = -lu.solve(k.middleRows(6 * n, 6));
    a.block(dofs + 6 * n, dofs, 6, dofs) = -lu.solve(c.middleRows(6 * n, 6));
  }
  const Eigen::EigenSolver<MatX> eig(a, true);
  std::vector<DampedMode> modes;
  for (int i = 0; i < 2 * dofs; ++i) {
    const std::complex<double> lambda = eig.eigenvalues()[i];
    if (lambda.imag() < 0.0) continue;
    DampedMode mode;
    mode.eigenvalue = lambda;
    const Eigen::VectorXcd x = eig.eigenvectors().col(i).head(dofs);
    for (int n = 0; n < model.node_count(); ++n)
      for (int k6 = 0; k6 < 6; ++k6) mode.share(k6) += std::norm(x(6 * n + k6));
    for (int group = 0; group < 2; ++group) {
      const double total = mode.share.segment<3>(3 * group).sum();
      if (total > 0.0) mode.share.segment<3>(3 * group) /= total;
    }
    mode.shape = x;
    modes.push_back(mode);
  }
  std::sort(modes.begin(), modes.end(),
            [](const DampedMode& p, const DampedMode& q) { return std::abs(p.eigenvalue) < std::abs(q.eigenvalue); });
  return modes;
}

}  // namespace fowtsim::beam
