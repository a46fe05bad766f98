#pragma once
// One record of a linear quantity at a fixed horizontal position, by one inverse FFT:
//   q(t_j) = Σ_n Re[T_n A_n e^{i(ω_n t_j − k_n s)}],  t_j = j D / M,  M = fft.size(),
// where T_n = transfer(component) is the quantity's complex transfer function (1 for η) and
// s = x cos β + y sin β. The FFT coefficients are c_n = T_n A_n e^{−i k_n s} / 2 (the c2r transform
// adds the conjugate half; a Nyquist coefficient, 2n = M, is not halved).
#include <cmath>
#include <complex>
#include <cstddef>

#include "fowtsim/core/fft.hpp"
#include "fowtsim/waves/wave_field.hpp"

namespace fowtsim::waves::detail {

template <class Transfer>
void synthesise(const WaveField& field, InverseRealFft& fft, double s_m, Transfer&& transfer, double* out,
                std::size_t stride) {
  fft.clear();
  std::complex<double>* c = fft.coefficients();
  for (const WaveComponent& w : field.components()) {
    const double phase = -w.wavenumber_rad_m * s_m;
    // c2r counts a Nyquist coefficient (2n = M) once, real part only: that is Re[T A e^{−iks} e^{iπj}]
    // exactly on the samples when it is not halved (replayed records of even length, m = 1).
    const double half = 2 * w.harmonic == fft.size() ? 1.0 : 0.5;
    c[w.harmonic] = half * transfer(w) * w.amplitude_m * std::complex<double>(std::cos(phase), std::sin(phase));
  }
  const double* y = fft.execute();
  for (std::size_t j = 0; j < fft.size(); ++j) out[j * stride] = y[j];
}

}  // namespace fowtsim::waves::detail
