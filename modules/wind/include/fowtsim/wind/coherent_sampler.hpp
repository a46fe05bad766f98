#pragma once
// Draws, for one frequency, complex amplitudes X_j at the points of a regular y–z grid whose
// covariance E[X Xᴴ] is the IEC u-coherence matrix C_jk = exp(−a |r_j − r_k|) (IEC 61400-1 ed. 3
// eq. B.2 with a = a(f)), from unit-modulus random phasors ξ (Veers 1988: E[ξ ξᴴ] = I).
//
// Three exact-or-bounded ways, chosen per frequency (the cost Veers pays is a dense Cholesky of the
// n×n matrix, n = ny·nz = 961 for the OC3 grid, at every frequency):
//   independent  nearest-neighbour coherence exp(−a·min(dy, dz)) < 1e-4: C is replaced by I
//                (the only approximation: every dropped entry is below 1e-4);
//   embedding    C is block-Toeplitz with Toeplitz blocks on the grid; it is embedded in a
//                My×Mz block-circulant matrix (My >= 2(ny−1), Mz >= 2(nz−1)) whose eigenvalues are
//                one 2-D FFT of its first row; if none is negative (Dietrich & Newsam 1997, SIAM
//                J. Sci. Comput. 18(4)), X = F (sqrt(λ / (My Mz)) ⊙ ξ) restricted to the grid has
//                covariance exactly C (O(M log M) per frequency);
//   dense        otherwise (lowest frequencies, where the correlation length exceeds the grid):
//                Veers' X = L ξ with C = L Lᵀ, factorised in the basis Q of the grid's two mirror
//                symmetries, where QᵀCQ is block-diagonal (four parity classes of about n/4
//                points): X = Q blockdiag(L_k) ξ, exact, for 1/16 of the cost of one n×n Cholesky.
// Workspace is allocated at construction; prepare() and sample() do not allocate, except dense
// prepare() (four factorisations of about n/4, a handful of frequencies per field).
#include <complex>
#include <cstddef>
#include <memory>
#include <span>

namespace fowtsim::wind {

class CoherentSampler {
 public:
  enum class Method { independent, embedding, dense };

  // Grid point j = iz·ny + iy at (iy·dy, iz·dz).
  CoherentSampler(int ny, int nz, double dy_m, double dz_m);
  ~CoherentSampler();
  CoherentSampler(const CoherentSampler&) = delete;
  CoherentSampler& operator=(const CoherentSampler&) = delete;

  // Chooses and sets up the method for coherence decay a [1/m] (see above).
  Method prepare(double decay_per_m);
  // Number of phasors sample() consumes for the prepared method.
  std::size_t draws() const;
  // out[j] for the n grid points from xi (size draws()).
  void sample(std::span<const std::complex<double>> xi, std::span<std::complex<double>> out);

  std::size_t point_count() const;
  std::size_t embedding_size() const;  // My·Mz
  // Largest coherence set to zero so far by the independent switch [-] (<= 1e-4).
  double max_dropped_coherence() const;

  static constexpr double independence_threshold = 1e-4;  // dropped coherence bound [-]

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fowtsim::wind
