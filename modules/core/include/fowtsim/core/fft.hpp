#pragma once
// The discrete Fourier transforms of the modules, through FFTW (unnormalised, as FFTW defines
// them). Each object owns FFTW-aligned buffers; the plans come from one process-wide cache, one
// plan per kind and size, made under a mutex because FFTW's planner is not thread-safe (FFTW
// manual §5.2) and run on each object's buffers by the new-array execute functions, which are.
// Plans are made with FFTW_ESTIMATE, which picks the algorithm from the size and the buffers'
// alignment alone: the same size gives the same arithmetic, hence bit-identical results run to run
// and thread to thread (FFTW_MEASURE times candidates and may not). Objects may live on any
// thread; one object is not for two threads at once.
#include <complex>
#include <cstddef>

struct fftw_plan_s;  // FFTW's plan type; fftw3.h stays private to core

namespace fowtsim {

// Inverse real DFT of length N (FFTW c2r):
//   y_j = Σ_{n=0}^{N−1} c_n e^{2πi jn/N},  j = 0 … N−1,  c_{N−n} = conj(c_n),
// given c_0 … c_{N/2}.
class InverseRealFft {
 public:
  explicit InverseRealFft(std::size_t n);
  ~InverseRealFft();
  InverseRealFft(const InverseRealFft&) = delete;
  InverseRealFft& operator=(const InverseRealFft&) = delete;

  std::size_t size() const { return n_; }
  // Coefficients c_0 … c_{N/2} (N/2 + 1 entries); zero after construction and clear().
  std::complex<double>* coefficients() { return in_; }
  void clear();
  // Runs the transform; the coefficients are destroyed (FFTW c2r), the result stays valid until
  // the next execute().
  const double* execute();

 private:
  std::size_t n_;
  std::complex<double>* in_ = nullptr;
  double* out_ = nullptr;
  fftw_plan_s* plan_ = nullptr;
};

// Forward real DFT of length N (FFTW r2c):
//   X_n = Σ_{j=0}^{N−1} x_j e^{−2πi jn/N},  n = 0 … N/2.
class ForwardRealFft {
 public:
  explicit ForwardRealFft(std::size_t n);
  ~ForwardRealFft();
  ForwardRealFft(const ForwardRealFft&) = delete;
  ForwardRealFft& operator=(const ForwardRealFft&) = delete;

  std::size_t size() const { return n_; }
  double* samples() { return in_; }  // x_0 … x_{N−1}; zero after construction
  // Runs the transform (the samples are kept); the result (N/2 + 1 entries) stays valid until
  // the next execute().
  const std::complex<double>* execute();

 private:
  std::size_t n_;
  double* in_ = nullptr;
  std::complex<double>* out_ = nullptr;
  fftw_plan_s* plan_ = nullptr;
};

// Forward two-dimensional complex DFT in place over `rows` × `cols` values stored row by row
// (the column index fastest):
//   X_{k,l} = Σ_{r,c} x_{r,c} e^{−2πi (kr/rows + lc/cols)}.
class ForwardComplexFft2d {
 public:
  ForwardComplexFft2d(std::size_t rows, std::size_t cols);
  ~ForwardComplexFft2d();
  ForwardComplexFft2d(const ForwardComplexFft2d&) = delete;
  ForwardComplexFft2d& operator=(const ForwardComplexFft2d&) = delete;

  std::size_t size() const { return rows_ * cols_; }
  std::complex<double>* data() { return data_; }  // x before execute(), X after; zero after construction
  void execute();

 private:
  std::size_t rows_, cols_;
  std::complex<double>* data_ = nullptr;
  fftw_plan_s* plan_ = nullptr;
};

}  // namespace fowtsim
