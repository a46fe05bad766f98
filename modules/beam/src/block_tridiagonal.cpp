#include "fowtsim/beam/block_tridiagonal.hpp"

#include <cmath>

namespace fowtsim::beam {

void BlockTridiagonal::resize(int blocks) {
  diag_.assign(blocks, Mat6::Zero());
  upper_.assign(blocks > 0 ? blocks - 1 : 0, Mat6::Zero());
  lower_.assign(blocks > 0 ? blocks - 1 : 0, Mat6::Zero());
  pivots_.assign(blocks, Eigen::PartialPivLU<Mat6>());
}

void BlockTridiagonal::set_zero() {
  for (auto& b : diag_) b.setZero();
  for (auto& b : upper_) b.setZero();
  for (auto& b : lower_) b.setZero();
}

void BlockTridiagonal::multiply(const VecX& x, VecX& y) const {
  const int n = blocks();
  for (int i = 0; i < n; ++i) {
    Vec6 acc = diag_[i] * x.segment<6>(6 * i);
    if (i > 0) acc += lower_[i - 1] * x.segment<6>(6 * (i - 1));
    if (i + 1 < n) acc += upper_[i] * x.segment<6>(6 * (i + 1));
    y.segment<6>(6 * i) = acc;
  }
}

MatX BlockTridiagonal::dense() const {
  const int n = blocks();
  MatX a = MatX::Zero(6 * n, 6 * n);
  for (int i = 0; i < n; ++i) {
    a.block<6, 6>(6 * i, 6 * i) = diag_[i];
    if (i + 1 < n) {
      a.block<6, 6>(6 * i, 6 * i + 6) = upper_[i];
      a.block<6, 6>(6 * i + 6, 6 * i) = lower_[i];
    }
  }
  return a;
}

bool BlockTridiagonal::factor() {
  // D'_0 = D_0;  L'_{i} = L_i D'_i⁻¹;  D'_{i+1} = D_{i+1} − L'_i U_i.
  const int n = blocks();
  for (int i = 0; i < n; ++i) {
    if (i > 0) diag_[i].noalias() -= lower_[i - 1] * upper_[i - 1];
    pivots_[i].compute(diag_[i]);
    const double det = pivots_[i].determinant();
    if (!std::isfinite(det) || det == 0.0) return false;
    if (i + 1 < n) lower_[i] = lower_[i] * pivots_[i].inverse();
  }
  return true;
}

void BlockTridiagonal::solve_in_place(VecX& b) const {
  const int n = blocks();
  for (int i = 1; i < n; ++i) b.segment<6>(6 * i) -= lower_[i - 1] * b.segment<6>(6 * (i - 1));
  for (int i = n - 1; i >= 0; --i) {
    Vec6 rhs = b.segment<6>(6 * i);
    if (i + 1 < n) rhs -= upper_[i] * b.segment<6>(6 * (i + 1));
    b.segment<6>(6 * i) = pivots_[i].solve(rhs);
  }
}

}  // namespace fowtsim::beam
