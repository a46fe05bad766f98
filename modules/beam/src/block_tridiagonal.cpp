#include "fowtsim/beam/block_tridiagonal.hpp"

#include <cmath>

namespace fowtsim::beam {
namespace {

// Gauss–Jordan inverse of a 6×6 block with partial pivoting on the row-major augmented matrix
// [A | I]: each row operation then runs over 12 contiguous doubles (vectorised). For blocks this
// small, several times faster than Eigen's general LU solve with a matrix right-hand side.
bool invert_block(const Mat6& a, Mat6& inverse) {
  Eigen::Matrix<double, 6, 12, Eigen::RowMajor> m;
  m.leftCols<6>() = a;
  m.rightCols<6>().setIdentity();
  for (int c = 0; c < 6; ++c) {
    int pivot = c;
    double largest = std::abs(m(c, c));
    for (int r = c + 1; r < 6; ++r) {
      const double v = std::abs(m(r, c));
      if (v > largest) {
        largest = v;
        pivot = r;
      }
    }
    if (largest == 0.0 || !std::isfinite(largest)) return false;
    if (pivot != c) m.row(pivot).swap(m.row(c));
    m.row(c) *= 1.0 / m(c, c);
    for (int r = 0; r < 6; ++r) {
      const double f = m(r, c);
      if (r != c && f != 0.0) m.row(r) -= f * m.row(c);
    }
  }
  inverse = m.rightCols<6>();
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

void BlockTridiagonal::solve_in_place(VecX& b1, VecX& b2) const {
  const int n = blocks();
  using Pair = Eigen::Matrix<double, 6, 2>;
  const auto pair = [&](int i) {
    Pair p;
    p << b1.segment<6>(6 * i), b2.segment<6>(6 * i);
    return p;
  };
  const auto store = [&](int i, const Pair& p) {
    b1.segment<6>(6 * i) = p.col(0);
    b2.segment<6>(6 * i) = p.col(1);
  };
  Pair previous = pair(0);
  for (int i = 1; i < n; ++i) {
    previous = pair(i) - lower_[i - 1] * previous;
    store(i, previous);
  }
  Pair next = Pair::Zero();
  for (int i = n - 1; i >= 0; --i) {
    Pair rhs = pair(i);
    if (i + 1 < n) rhs -= upper_[i] * next;
    next = pivot_inverses_[i] * rhs;
    store(i, next);
  }
}

}  // namespace fowtsim::beam
