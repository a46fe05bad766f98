#include "fft.hpp"

#include <algorithm>
#include <mutex>
#include <new>

#include <fftw3.h>

namespace fowtsim::waves::detail {
namespace {
std::mutex& planner_mutex() {
  static std::mutex m;  // FFTW's planner is not thread-safe (FFTW manual §5.2)
  return m;
}
}  // namespace

InverseRealFft::InverseRealFft(std::size_t n) : n_(n) {
  in_ = reinterpret_cast<std::complex<double>*>(fftw_malloc(sizeof(fftw_complex) * (n / 2 + 1)));
  out_ = static_cast<double*>(fftw_malloc(sizeof(double) * n));
  if (!in_ || !out_) {
    fftw_free(in_);
    fftw_free(out_);
    throw std::bad_alloc();
  }
  clear();
  std::lock_guard lock(planner_mutex());
  plan_ = fftw_plan_dft_c2r_1d(static_cast<int>(n), reinterpret_cast<fftw_complex*>(in_), out_, FFTW_ESTIMATE);
}

InverseRealFft::~InverseRealFft() {
  {
    std::lock_guard lock(planner_mutex());
    if (plan_) fftw_destroy_plan(static_cast<fftw_plan>(plan_));
  }
  fftw_free(in_);
  fftw_free(out_);
}

void InverseRealFft::clear() { std::fill(in_, in_ + n_ / 2 + 1, std::complex<double>(0.0, 0.0)); }

const double* InverseRealFft::execute() {
  fftw_execute(static_cast<fftw_plan>(plan_));
  return out_;
}

ForwardRealFft::ForwardRealFft(std::size_t n) : n_(n) {
  in_ = static_cast<double*>(fftw_malloc(sizeof(double) * n));
  out_ = reinterpret_cast<std::complex<double>*>(fftw_malloc(sizeof(fftw_complex) * (n / 2 + 1)));
  if (!in_ || !out_) {
    fftw_free(in_);
    fftw_free(out_);
    throw std::bad_alloc();
  }
  std::fill(in_, in_ + n_, 0.0);
  std::lock_guard lock(planner_mutex());
  plan_ = fftw_plan_dft_r2c_1d(static_cast<int>(n), in_, reinterpret_cast<fftw_complex*>(out_), FFTW_ESTIMATE);
}

ForwardRealFft::~ForwardRealFft() {
  {
    std::lock_guard lock(planner_mutex());
    if (plan_) fftw_destroy_plan(static_cast<fftw_plan>(plan_));
  }
  fftw_free(in_);
  fftw_free(out_);
}

const std::complex<double>* ForwardRealFft::execute() {
  fftw_execute(static_cast<fftw_plan>(plan_));
  return out_;
}

}  // namespace fowtsim::waves::detail
