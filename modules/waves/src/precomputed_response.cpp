#include "fowtsim/waves/precomputed_response.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fowtsim/core/fft.hpp"
#include "fowtsim/core/interpolation.hpp"
#include "synthesis.hpp"

namespace fowtsim::waves {

PrecomputedResponse::PrecomputedResponse(const WaveField& field, std::span<const Transfer> transfers,
                                         double samples_per_shortest_period)
    : channels_(transfers.size()), duration_s_(field.record_duration_s()) {
  const double f_max = field.calm() ? 0.0 : field.components().back().omega_rad_s / (2.0 * std::numbers::pi);
  const auto oversampling = std::max<std::size_t>(
      1, static_cast<std::size_t>(std::ceil(samples_per_shortest_period * f_max * field.record_dt_s() - 1e-9)));
  samples_ = field.record_samples() * oversampling;
  storage_.assign(channels_ * samples_, 0.0);
  if (field.calm()) return;
  InverseRealFft fft(samples_);
  for (std::size_t c = 0; c < channels_; ++c)
    detail::synthesise(field, fft, 0.0, [&](const WaveComponent& w) { return transfers[c](w.omega_rad_s); },
                       storage_.data() + c * samples_, 1);
}

double PrecomputedResponse::value(std::size_t channel, double t_s) const {
  const PeriodicStencil ps = periodic_cubic_stencil(t_s, duration_s_, samples_);
  const double* y = storage_.data() + channel * samples_;
  return ps.weight[0] * y[ps.index[0]] + ps.weight[1] * y[ps.index[1]] + ps.weight[2] * y[ps.index[2]] +
         ps.weight[3] * y[ps.index[3]];
}

}  // namespace fowtsim::waves
