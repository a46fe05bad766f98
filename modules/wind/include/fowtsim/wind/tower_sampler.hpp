#pragma once
// Tower points of a generated field: the single column TurbSim writes below the grid, and their
// u amplitudes per frequency drawn jointly with (conditionally on) the grid's.
//
// Layout (TurbSim, OpenFAST modules/turbsim/src/TSsubs.f90, subroutine CreateGrid, "the tower
// 'lollipop' points"): NTwrPts = INT((Zbottom − Tolerance) / GridRes_Z); if NTwrPts < 1 there are no
// tower points ("There are no extra tower data points below the grid"), otherwise NTwrIndx =
// NTwrPts + 1 points at Y = 0, Z = Zbottom − (IZ−1)·GridRes_Z, IZ = 1..NTwrIndx: the first at the
// grid's bottom height, the last above the ground by more than Tolerance. With an odd NumGrid_Y the
// first one *is* the grid's bottom-centre point (TwrPtIndx(1) = GridPtIndx(NumGrid_Y/2 + 1)); with an
// even NumGrid_Y it is an extra point ("ExtraTwrPT") between the two centre columns. TurbSim puts all
// these points in the one coherence matrix of its IEC method (CalcFourierCoeffs_IEC: distances between
// every pair of points), i.e. the tower is coherent with the grid. The OC3 file (31×31 grid, z_bottom
// 17.5 m, dz 4.833 m) has INT(17.5/4.833) + 1 = 4 tower points, as our reader finds in it.
//
// Joint sampling (exact second moments). Per frequency the grid amplitudes X_g come from the
// CoherentSampler unchanged (same draws, same values: adding tower points does not alter the grid).
// The tower amplitudes are drawn from the conditional law given the grid,
//     X_t = C_tg C_gg⁻¹ X_g + S^{1/2} η,   S = C_tt − C_tg C_gg⁻¹ C_gt,   η independent unit phasors,
// so that E[X_t X_tᴴ] = C_tt and E[X_t X_gᴴ] = C_tg exactly (to round-off) whenever E[X_g X_gᴴ] = C_gg,
// i.e. for the embedding and dense frequencies of the grid. The solve is reduced by symmetry: C_gg
// commutes with the reflection y → −y and the tower lies on its axis, so C_tg is zero on the
// antisymmetric subspace and C_tg C_gg⁻¹ X_g = C_ts C_ss⁻¹ Q_sᵀ X_g with Q_s the orthonormal symmetric
// basis (one basis vector per row and |y|: nz·⌈ny/2⌉ unknowns instead of ny·nz; 8× less work for the
// Cholesky). S^{1/2} by a symmetric eigen-decomposition with eigenvalues clamped at 0 (S is singular
// only by round-off).
//   Where the grid was drawn independently (its coherences < 1e-4 dropped) the tower is conditioned on
// that realised grid covariance, C_gg = I, which keeps E[X_t X_gᴴ] = C_tg exact there too; where every
// coherence of a tower point with any other point is < 1e-4 the tower points are drawn independently
// (the generator's one approximation, same threshold).
#include <complex>
#include <cstddef>
#include <memory>
#include <span>

namespace fowtsim::wind {

// Number of TurbSim tower points below a grid with bottom height z_bottom and spacing dz [m]
// (0 if none fits above the ground); TurbSim's Tolerance taken as 1e-4 m.
int turbsim_tower_point_count(double z_bottom_m, double dz_m);

class TowerSampler {
 public:
  enum class Method { independent, conditional };

  // Grid ny × nz with spacings dy, dz; n_tower points at y = 0, depth k·dz below the bottom row.
  TowerSampler(int ny, int nz, double dy_m, double dz_m, int n_tower);
  ~TowerSampler();
  TowerSampler(const TowerSampler&) = delete;
  TowerSampler& operator=(const TowerSampler&) = delete;

  // Tower point 0 is the grid's bottom-centre point (odd ny): copied, not drawn.
  bool first_on_grid() const;
  // Index of that grid point (iz = 0, iy = (ny−1)/2).
  std::size_t first_grid_index() const;
  // Number of drawn tower points (n_tower, or n_tower − 1 when the first is on the grid).
  std::size_t draws() const;

  // Prepares the frequency with coherence exp(−a r); grid_exact: the grid amplitudes have covariance
  // C_gg (embedding, dense), false: identity (the grid's independent switch).
  Method prepare(double a_per_m, bool grid_exact);

  // Tower amplitudes of the drawn points (out.size() == draws()) from the grid's (ny·nz) and draws()
  // independent unit phasors eta. No allocation.
  void sample(std::span<const std::complex<double>> grid_x, std::span<const std::complex<double>> eta,
              std::span<std::complex<double>> out);

  double max_dropped_coherence() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fowtsim::wind
