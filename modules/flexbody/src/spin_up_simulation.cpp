#include "fowtsim/flexbody/spin_up_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "fowtsim/core/error.hpp"

namespace fowtsim::flexbody {

std::vector<double> spin_up_tip_history(const SpinningBeam& beam, const HubSpin& hub, double end_s,
                                        double sample_s, double max_step_s) {
  if (!(end_s >= 0.0) || !(sample_s > 0.0) || !(max_step_s > 0.0))
    throw InputError({"flexbody", std::nullopt, "spin-up run", "end ≥ 0, sample > 0, step > 0"},
                     "bad spin-up time settings");
  const int n = beam.size();
  const auto rate = [&](double t, const Eigen::VectorXd& y) {
    Eigen::VectorXd out(2 * n);
    out.head(n) = y.tail(n);
    out.tail(n) = beam.acceleration(y.head(n), hub.rate(t), hub.acceleration(t));
    return out;
  };
  const long samples = std::lround(end_s / sample_s);
  const long substeps = std::max(1L, static_cast<long>(std::ceil(sample_s / max_step_s - 1e-9)));
  const double dt = sample_s / static_cast<double>(substeps);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(2 * n);
  std::vector<double> tip{0.0};
  tip.reserve(static_cast<std::size_t>(samples) + 1);
  for (long k = 0; k < samples; ++k) {
    for (long s = 0; s < substeps; ++s) {
      const double t = static_cast<double>(k) * sample_s + static_cast<double>(s) * dt;
      const Eigen::VectorXd k1 = rate(t, y);
      const Eigen::VectorXd k2 = rate(t + dt / 2, y + dt / 2 * k1);
      const Eigen::VectorXd k3 = rate(t + dt / 2, y + dt / 2 * k2);
      const Eigen::VectorXd k4 = rate(t + dt, y + dt * k3);
      y += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    tip.push_back(beam.tip_deflection(y.head(n)));
  }
  return tip;
}

}  // namespace fowtsim::flexbody
