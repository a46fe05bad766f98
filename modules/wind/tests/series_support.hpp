#pragma once
// Helpers of the generator's statistical tests: a point's time series out of a generated grid and
// its one-sided DFT (core's FFT, as the generator itself uses).
#include <algorithm>
#include <complex>
#include <vector>

#include "fowtsim/core/fft.hpp"
#include "fowtsim/wind/full_field.hpp"

namespace fowtsim::wind::test_support {

using Complex = std::complex<double>;

// DFT_m of a real series, m = 0 … N/2.
inline std::vector<Complex> dft(const std::vector<double>& series) {
  ForwardRealFft fft(series.size());
  std::copy(series.begin(), series.end(), fft.samples());
  const Complex* out = fft.execute();
  return std::vector<Complex>(out, out + series.size() / 2 + 1);
}

// Component c (0 u, 1 v, 2 w) of grid point (iy, iz) over the whole record.
inline std::vector<double> series_at(const FullField& f, int iy, int iz, int c) {
  std::vector<double> s(f.nt);
  for (int it = 0; it < f.nt; ++it) s[it] = f.grid[((static_cast<std::size_t>(it) * f.nz + iz) * f.ny + iy) * 3 + c];
  return s;
}

}  // namespace fowtsim::wind::test_support
