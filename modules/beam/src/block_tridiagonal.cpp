#include "fowtsim/beam/block_tridiagonal.hpp"

#include <cmath>

namespace fowtsim::beam {
namespace {

// Gauss–Jordan inverse of a 6×6 block with partial pivoting, in fixed-size loops: for blocks this
// small, several times faster than Eigen's general LU solve with a matrix right-hand side.
bool invert_block(Mat6 a, Mat6& inverse) {
  inverse.setIdentity();
  for (int c = 0; c < 6; ++c) {
    int pivot = c;
    for (int r = c + 1; r < 6; ++r)
      if (std::abs(a(r, c)) > std::abs(a(pivot, c))) pivot = r;
    const double p = a(pivot, c);
    if (p == 0.0 || !std::isfinite(p)) return false;
    if (pivot != c) {
      a.row(pivot).swap(a.row(c));
      inverse.row(pivot).swap(inverse.row(c));
    }
    a.row(c) /= p;
    inverse.row(c) /= p;
    for (int r = 0; r < 6; ++r) {
      if (r == c || a(r, c) == 0.0) continue;
      const double f = a(r, c);
      a.row(r) -= f * a.row(c);
      inverse.row(r) -= f * inverse.row(c);
    }
  }
  return true;
}

}  // namespace

void BlockTridiagonal::resize(int blocks) {
  diag_.assign(blocks, Mat6::Zero());
  upper_.assign(blocks > 0 ? blocks - 1 : 0, Mat6::Zero());
  lower_.assign(blocks > 0 ? blocks - 1 : 0, Mat6::Zero());
  pivot_inverses_.assign(blocks, Mat6::Zero());
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
    if (!invert_block(diag_[i], pivot_inverses_[i])) return false;
    if (i + 1 < n) lower_[i] = lower_[i] * pivot_inverses_[i];
  }
  return true;
}

void BlockTridiagonal::solve_in_place(VecX& b) const {
  const int n = blocks();
  for (int i = 1; i < n; ++i) b.segment<6>(6 * i) -= lower_[i - 1] * b.segment<6>(6 * (i - 1));
  for (int i = n - 1; i >= 0; --i) {
    Vec6 rhs = b.segment<6>(6 * i);
    if (i + 1 < n) rhs -= upper_[i] * b.segment<6>(6 * (i + 1));
    b.segment<6>(6 * i) = pivot_inverses_[i] * rhs;
  }
}

}  // namespace fowtsim::beam
