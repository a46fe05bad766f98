#pragma once
// Inverse real FFT through FFTW (private to the waves module):
//   y_j = Σ_{n=0}^{N−1} c_n e^{2πi jn/N},  j = 0 … N−1,  c_{N−n} = conj(c_n)
// given c_0 … c_{N/2} (FFTW c2r, unnormalised). Plans are made with FFTW_ESTIMATE, which picks the
// algorithm from the size alone: the same N gives the same arithmetic, hence bit-identical
// results run to run (FFTW_MEASURE times candidates and may not). FFTW's planner is not
// thread-safe; plan creation and destruction are serialised by a mutex inside.
#include <complex>
#include <cstddef>

namespace fowtsim::waves::detail {

class InverseRealFft {
 public:
  explicit InverseRealFft(std::size_t n);
  ~InverseRealFft();
  InverseRealFft(const InverseRealFft&) = delete;
  InverseRealFft& operator=(const InverseRealFft&) = delete;

  std::size_t size() const { return n_; }
  // Coefficients c_0 … c_{N/2} (N/2 + 1 entries); zeroed by clear().
  std::complex<double>* coefficients() { return in_; }
  void clear();
  // Runs the transform; the coefficients are destroyed (FFTW c2r), the result stays valid until
  // the next execute().
  const double* execute();

 private:
  std::size_t n_ = 0;
  std::complex<double>* in_ = nullptr;
  double* out_ = nullptr;
  void* plan_ = nullptr;
};

// Forward real FFT through FFTW (r2c, unnormalised), FFTW_ESTIMATE as above:
//   X_n = Σ_{j=0}^{N−1} x_j e^{−2πi jn/N},  n = 0 … N/2.
class ForwardRealFft {
 public:
  explicit ForwardRealFft(std::size_t n);
  ~ForwardRealFft();
  ForwardRealFft(const ForwardRealFft&) = delete;
  ForwardRealFft& operator=(const ForwardRealFft&) = delete;

  std::size_t size() const { return n_; }
  double* samples() { return in_; }  // x_0 … x_{N−1}
  // Runs the transform; the result (N/2 + 1 entries) stays valid until the next execute().
  const std::complex<double>* execute();

 private:
  std::size_t n_ = 0;
  double* in_ = nullptr;
  std::complex<double>* out_ = nullptr;
  void* plan_ = nullptr;
};

}  // namespace fowtsim::waves::detail
