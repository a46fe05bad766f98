#include "fowtsim/core/fft.hpp"

#include <fftw3.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <new>
#include <tuple>

namespace fowtsim {
namespace {

enum class Kind { inverse_real, forward_real, forward_complex_2d };

template <class T>
T* allocate(std::size_t count) {
  void* p = fftw_malloc(sizeof(T) * count);
  if (p == nullptr) throw std::bad_alloc();
  return static_cast<T*>(p);
}

fftw_complex* as_fftw(std::complex<double>* p) { return reinterpret_cast<fftw_complex*>(p); }

// One plan per kind and size for the whole process. The planning buffers are FFTW-aligned like
// every object's own, so the plans run on those through the new-array execute functions; they
// are freed once the plan is made (a plan only executed on new arrays never touches them).
class PlanCache {
 public:
  ~PlanCache() {
    for (auto& entry : plans_) fftw_destroy_plan(entry.second);
  }

  fftw_plan get(Kind kind, std::size_t n0, std::size_t n1 = 0) {
    const std::lock_guard lock(mutex_);
    const auto key = std::make_tuple(kind, n0, n1);
    if (const auto it = plans_.find(key); it != plans_.end()) return it->second;
    return plans_.emplace(key, make(kind, n0, n1)).first->second;
  }

 private:
  static fftw_plan make(Kind kind, std::size_t n0, std::size_t n1) {
    const int i0 = static_cast<int>(n0), i1 = static_cast<int>(n1);
    fftw_plan plan = nullptr;
    switch (kind) {
      case Kind::inverse_real: {
        fftw_complex* in = fftw_alloc_complex(n0 / 2 + 1);
        double* out = fftw_alloc_real(n0);
        if (in && out) plan = fftw_plan_dft_c2r_1d(i0, in, out, FFTW_ESTIMATE);
        fftw_free(in);
        fftw_free(out);
        break;
      }
      case Kind::forward_real: {
        double* in = fftw_alloc_real(n0);
        fftw_complex* out = fftw_alloc_complex(n0 / 2 + 1);
        if (in && out) plan = fftw_plan_dft_r2c_1d(i0, in, out, FFTW_ESTIMATE);
        fftw_free(in);
        fftw_free(out);
        break;
      }
      case Kind::forward_complex_2d: {
        fftw_complex* data = fftw_alloc_complex(n0 * n1);
        if (data) plan = fftw_plan_dft_2d(i0, i1, data, data, FFTW_FORWARD, FFTW_ESTIMATE);
        fftw_free(data);
        break;
      }
    }
    if (plan == nullptr) throw std::bad_alloc();
    return plan;
  }

  std::mutex mutex_;
  std::map<std::tuple<Kind, std::size_t, std::size_t>, fftw_plan> plans_;
};

fftw_plan cached_plan(Kind kind, std::size_t n0, std::size_t n1 = 0) {
  static PlanCache cache;
  return cache.get(kind, n0, n1);
}

}  // namespace

InverseRealFft::InverseRealFft(std::size_t n)
    : n_(n), plan_(cached_plan(Kind::inverse_real, n)) {
  in_ = allocate<std::complex<double>>(n / 2 + 1);
  try {
    out_ = allocate<double>(n);
  } catch (...) {
    fftw_free(in_);
    throw;
  }
  clear();
}

InverseRealFft::~InverseRealFft() {
  fftw_free(in_);
  fftw_free(out_);
}

void InverseRealFft::clear() { std::fill(in_, in_ + n_ / 2 + 1, std::complex<double>(0.0, 0.0)); }

const double* InverseRealFft::execute() {
  fftw_execute_dft_c2r(plan_, as_fftw(in_), out_);
  return out_;
}

ForwardRealFft::ForwardRealFft(std::size_t n) : n_(n), plan_(cached_plan(Kind::forward_real, n)) {
  in_ = allocate<double>(n);
  try {
    out_ = allocate<std::complex<double>>(n / 2 + 1);
  } catch (...) {
    fftw_free(in_);
    throw;
  }
  std::fill(in_, in_ + n_, 0.0);
}

ForwardRealFft::~ForwardRealFft() {
  fftw_free(in_);
  fftw_free(out_);
}

const std::complex<double>* ForwardRealFft::execute() {
  fftw_execute_dft_r2c(plan_, in_, as_fftw(out_));
  return out_;
}

ForwardComplexFft2d::ForwardComplexFft2d(std::size_t rows, std::size_t cols)
    : rows_(rows), cols_(cols), plan_(cached_plan(Kind::forward_complex_2d, rows, cols)) {
  data_ = allocate<std::complex<double>>(rows * cols);
  std::fill(data_, data_ + rows * cols, std::complex<double>(0.0, 0.0));
}

ForwardComplexFft2d::~ForwardComplexFft2d() { fftw_free(data_); }

void ForwardComplexFft2d::execute() { fftw_execute_dft(plan_, as_fftw(data_), as_fftw(data_)); }

}  // namespace fowtsim
