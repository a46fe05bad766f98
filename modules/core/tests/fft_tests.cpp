// The FFT wrappers against transforms known in closed form, and the plan cache under threads.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <functional>
#include <numbers>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/core/fft.hpp"

using namespace fowtsim;

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// A deterministic, non-periodic real record of length n.
std::vector<double> record(std::size_t n) {
  std::vector<double> x(n);
  for (std::size_t j = 0; j < n; ++j) x[j] = std::sin(0.37 * j * j + 1.0) + 0.2 * std::cos(1.3 * j);
  return x;
}

std::vector<std::complex<double>> forward(const std::vector<double>& x) {
  ForwardRealFft fft(x.size());
  std::copy(x.begin(), x.end(), fft.samples());
  const std::complex<double>* out = fft.execute();
  return {out, out + x.size() / 2 + 1};
}

}  // namespace

TEST_CASE("inverse real FFT of one harmonic is a cosine", "[unit][fft]") {
  // c_2 = 1/2 and its conjugate c_{N−2}: y_j = cos(2π 2j/N).
  InverseRealFft fft(16);
  fft.coefficients()[2] = {0.5, 0.0};
  const double* y = fft.execute();
  for (int j = 0; j < 16; ++j) CHECK(y[j] == Approx(std::cos(kTwoPi * 2 * j / 16)).margin(1e-15));  // a few roundings of 1
}

TEST_CASE("forward real FFT of a cosine is N/2 at its harmonic and zero elsewhere", "[unit][fft]") {
  constexpr std::size_t n = 48;  // 2⁴·3: FFTW's mixed-radix path
  std::vector<double> x(n);
  for (std::size_t j = 0; j < n; ++j) x[j] = std::cos(kTwoPi * 5.0 * j / n);
  const std::vector<std::complex<double>> big_x = forward(x);
  for (std::size_t k = 0; k <= n / 2; ++k) {
    const double expected = k == 5 ? 0.5 * n : 0.0;
    // Sums of n terms of size 1 with cos/sin rounded to 1e-16: 1e-13 covers them.
    CHECK(std::abs(big_x[k] - expected) < 1e-13);
  }
}

TEST_CASE("forward then inverse real FFT returns N times the record", "[unit][fft]") {
  for (std::size_t n : {7u, 64u, 1000u}) {  // odd, power of two, 2³·5³
    const std::vector<double> x = record(n);
    const std::vector<std::complex<double>> big_x = forward(x);
    InverseRealFft inverse(n);
    std::copy(big_x.begin(), big_x.end(), inverse.coefficients());
    const double* y = inverse.execute();
    double worst = 0.0;
    for (std::size_t j = 0; j < n; ++j) worst = std::max(worst, std::abs(y[j] / static_cast<double>(n) - x[j]));
    CHECK(worst < 1e-13);  // O(ε log n) relative error of FFTW on values of size 1
  }
}

TEST_CASE("two-dimensional forward FFT of a plane wave is one peak of height rows·cols", "[unit][fft]") {
  constexpr std::size_t rows = 6, cols = 10, k0 = 2, l0 = 7;
  ForwardComplexFft2d fft(rows, cols);
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < cols; ++c)
      fft.data()[r * cols + c] = std::polar(1.0, kTwoPi * (double(k0 * r) / rows + double(l0 * c) / cols));
  fft.execute();
  for (std::size_t k = 0; k < rows; ++k)
    for (std::size_t l = 0; l < cols; ++l) {
      const double expected = k == k0 && l == l0 ? double(rows * cols) : 0.0;
      CHECK(std::abs(fft.data()[k * cols + l] - expected) < 1e-12);  // 60 terms of size 1, rounded
    }
}

TEST_CASE("plans made and used from two threads give the results of one thread, bit for bit", "[unit][fft]") {
  // Both threads plan the same new sizes at once (the cache's mutex serialises FFTW's planner)
  // and run them; the main thread then reuses the cached plans. FFTW_ESTIMATE and aligned buffers
  // make one plan per size whoever makes it, so the transforms must agree exactly.
  std::vector<std::size_t> sizes;
  for (std::size_t n = 300; n < 340; ++n) sizes.push_back(n);
  std::vector<std::vector<std::complex<double>>> a(sizes.size()), b(sizes.size());
  const auto run = [&sizes](std::vector<std::vector<std::complex<double>>>& out) {
    for (std::size_t i = 0; i < sizes.size(); ++i) out[i] = forward(record(sizes[i]));
  };
  std::thread first(run, std::ref(a)), second(run, std::ref(b));
  first.join();
  second.join();
  int differing = 0;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const std::vector<std::complex<double>> serial = forward(record(sizes[i]));
    differing += a[i] != serial;
    differing += b[i] != serial;
  }
  CHECK(differing == 0);  // exact: no tolerance
}
