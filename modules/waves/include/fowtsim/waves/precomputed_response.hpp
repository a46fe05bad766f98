#pragma once
// Linear responses of a body to the sea, precomputed as records (issue 15: first-order wave
// excitation from a potential-flow transfer function, "no FFT per step"): for each channel c with
// transfer function H_c(ω) relative to the elevation at the origin,
//   y_c(t) = Σ_n Re[H_c(ω_n) A_n e^{iω_n t}]   (wave_field.hpp components),
// one inverse FFT per channel over the periodic record, stored at D/(N m) and read by the periodic
// 4-point Lagrange stencil of core/interpolation.hpp, as PrecomputedKinematics reads its series.
#include <complex>
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "fowtsim/waves/wave_field.hpp"

namespace fowtsim::waves {

class PrecomputedResponse {
 public:
  using Transfer = std::function<std::complex<double>(double omega_rad_s)>;
  // m is the smallest oversampling giving the highest component `samples_per_shortest_period`
  // samples per period (8: interpolation error ≤ 0.9 % at that component, far less below it).
  PrecomputedResponse(const WaveField& field, std::span<const Transfer> transfers,
                      double samples_per_shortest_period = 8.0);

  std::size_t size() const { return channels_; }
  // y_c(t), any t (the record repeats). Allocation free.
  double value(std::size_t channel, double t_s) const;

 private:
  std::size_t channels_ = 0;
  std::size_t samples_ = 0;
  double duration_s_ = 0.0;
  std::vector<double> storage_;  // [channel][sample]
};

}  // namespace fowtsim::waves
