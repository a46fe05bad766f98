#pragma once
// Helpers of the generator's statistical tests: a point's time series out of a generated grid and
// its one-sided DFT (FFTW, as the generator itself uses).
#include <complex>
#include <vector>

#include <fftw3.h>

#include "fowtsim/wind/full_field.hpp"

namespace fowtsim::wind::test_support {

using Complex = std::complex<double>;

// DFT_m of a real series, m = 0 … N/2.
inline std::vector<Complex> dft(const std::vector<double>& series) {
  const int n = static_cast<int>(series.size());
  std::vector<double> in(series);
  std::vector<Complex> out(n / 2 + 1);
  fftw_plan plan = fftw_plan_dft_r2c_1d(n, in.data(), reinterpret_cast<fftw_complex*>(out.data()), FFTW_ESTIMATE);
  fftw_execute(plan);
  fftw_destroy_plan(plan);
  return out;
}

// Component c (0 u, 1 v, 2 w) of grid point (iy, iz) over the whole record.
inline std::vector<double> series_at(const FullField& f, int iy, int iz, int c) {
  std::vector<double> s(f.nt);
  for (int it = 0; it < f.nt; ++it) s[it] = f.grid[((static_cast<std::size_t>(it) * f.nz + iz) * f.ny + iy) * 3 + c];
  return s;
}

}  // namespace fowtsim::wind::test_support
