#pragma once
// A sum of damped complex exponentials fitted to a sampled impulse response (issue 15: the
// state-space alternative to the radiation convolution),
//   K(t) ≈ Σ_m Re(w_m r_m e^{p_m t}),   Re p_m < 0,
// poles p_m by Kung's SVD realisation of the Hankel matrix of the samples (Kung 1978, "A new
// identification and model reduction algorithm via singular value decomposition"; the eigensystem
// realisation algorithm, Juang & Pappa 1985; used for radiation kernels by Taghipour, Perez & Moan
// 2008, Marine Structures 21:309), the residues r_m then by linear least squares on all samples
// (which keeps the fit honest when unstable poles are dropped). A conjugate pair is kept once with
// weight w = 2, a real pole with w = 1.
#include <complex>
#include <span>
#include <vector>

namespace fowtsim::hydro {

struct ExponentialTerm {
  std::complex<double> pole;     // p [1/s], Re p < 0
  std::complex<double> residue;  // r [unit of K]
  double weight = 1.0;           // 2 for one member of a conjugate pair, 1 for a real pole
};

struct ExponentialFit {
  std::vector<ExponentialTerm> terms;
  int order = 0;                  // realisation order (states, counting a pair as two)
  double relative_error = 0.0;    // ‖K_fit − K‖₂ / ‖K‖₂ over the samples
};

// Samples K(k Δt), k = 0 … n − 1 (n ≥ 8). Tries orders 1, 2, … up to max_order and returns the
// first whose relative error is below `tolerance`, else the best one found. All-zero samples give
// an empty fit with error 0.
ExponentialFit fit_exponentials(std::span<const double> samples, double dt_s, double tolerance, int max_order);

// The fit at time t.
double evaluate(const ExponentialFit& fit, double t_s);

}  // namespace fowtsim::hydro
