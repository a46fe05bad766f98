#include "fowtsim/flexbody/spin_up_simulation.hpp"

#include "fowtsim/core/error.hpp"
#include "fowtsim/flexbody/sampled_response.hpp"

namespace fowtsim::flexbody {

std::vector<double> spin_up_tip_history(const SpinningBeam& beam, const HubSpin& hub, double end_s,
                                        double sample_s, double max_step_s) {
  if (!(end_s >= 0.0) || !(sample_s > 0.0) || !(max_step_s > 0.0))
    throw InputError({"flexbody", std::nullopt, "spin-up run", "end ≥ 0, sample > 0, step > 0"},
                     "bad spin-up time settings");
  return sampled_response(
      beam.size(),
      [&](double t, const Eigen::VectorXd& q, const Eigen::VectorXd&) {
        return Eigen::VectorXd(beam.acceleration(q, hub.rate(t), hub.acceleration(t)));
      },
      [&](const Eigen::VectorXd& q) { return beam.tip_deflection(q); }, end_s, sample_s, max_step_s);
}

}  // namespace fowtsim::flexbody
