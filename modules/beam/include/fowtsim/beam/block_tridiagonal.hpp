#pragma once
// Block-tridiagonal matrices with 6×6 blocks: the structure of every assembled beam matrix (a
// section couples only its two neighbouring nodes). Storage and solve are O(N); the solve is block
// LU without pivoting across blocks (each 6×6 pivot block inverted by Gauss–Jordan with partial
// pivoting), which is stable for the block diagonally dominant systems a step produces
// (mass + Δt² stiffness).
// All storage is sized once; factor/solve do not allocate.
#include <array>
#include <vector>

#include "fowtsim/core/types.hpp"

namespace fowtsim::beam {

class BlockTridiagonal {
 public:
  BlockTridiagonal() = default;
  explicit BlockTridiagonal(int blocks) { resize(blocks); }
  void resize(int blocks);
  void set_zero();
  int blocks() const { return static_cast<int>(diag_.size()); }

  Mat6& diag(int n) { return diag_[n]; }            // (n, n)
  Mat6& upper(int n) { return upper_[n]; }          // (n, n+1)
  Mat6& lower(int n) { return lower_[n]; }          // (n+1, n)
  const Mat6& diag(int n) const { return diag_[n]; }
  const Mat6& upper(int n) const { return upper_[n]; }
  const Mat6& lower(int n) const { return lower_[n]; }

  // y = A x (x, y of length 6·blocks; y must not alias x).
  void multiply(const VecX& x, VecX& y) const;
  // The full matrix (for analysis and tests; allocates).
  MatX dense() const;

  // The storage — diagonal, upper, lower and (after factor()) pivot-inverse blocks — for
  // checkpoints that must restore a factored matrix bit for bit.
  std::array<const std::vector<Mat6>*, 4> storage() const { return {&diag_, &upper_, &lower_, &pivot_inverses_}; }
  std::array<std::vector<Mat6>*, 4> storage() { return {&diag_, &upper_, &lower_, &pivot_inverses_}; }

  // Factor in place (destroys the matrix) and solve A x = b; b is overwritten with x.
  // Returns false if a pivot block is singular.
  bool factor();
  void solve_in_place(VecX& b) const;
  // Two right-hand sides at once: the same result as two calls, the block products of the two
  // interleaved (independent work for the pipeline in a solve that is otherwise one chain).
  void solve_in_place(VecX& b1, VecX& b2) const;

 private:
  std::vector<Mat6> diag_, upper_, lower_;
  std::vector<Mat6> pivot_inverses_;  // D'_i⁻¹ after factor()
};

}  // namespace fowtsim::beam
