#include "verify/kane_spin_up.hpp"

#include <algorithm>
#include <cmath>

#include "fowtsim/beam/beam_outputs.hpp"
#include "fowtsim/beam/rotating_benchmarks.hpp"
#include "fowtsim/beam/solvers.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/flexbody/hub_spin.hpp"
#include "fowtsim/flexbody/spin_up_simulation.hpp"
#include "fowtsim/flexbody/spinning_beam.hpp"

namespace fowtsim::driver {
namespace {

constexpr double kEnd = 20.0;     // 15 s spin-up + 5 s at Ω_s [s]
constexpr double kSample = 0.02;  // common output grid [s]

std::vector<double> mbbt_tip(const flexbody::HubSpin& hub) {
  const beam::BeamModel model = beam::discretise(beam::benchmarks::kane_beam(), 30);
  std::vector<double> tip;
  mbbt_spin_up(model, hub, kEnd, kSample,
               [&](const beam::BeamState& state) { tip.push_back(beam::beam_outputs(model, state).tip_displacement_m.y()); });
  return tip;
}

std::vector<double> rr_tip(const flexbody::HubSpin& hub, int n) {
  std::vector<flexbody::ShapeFunction> shapes;
  for (int j = 1; j <= n; ++j) shapes.push_back(flexbody::clamped_free_mode(j, beam::benchmarks::kKaneLength));
  const flexbody::SpinningBeam rr(flexbody::uniform_beam(beam::benchmarks::kKaneLength, beam::benchmarks::kKaneMassPerLength,
                                                         beam::benchmarks::kKaneBendingStiffness),
                                  shapes);
  return flexbody::spin_up_tip_history(rr, hub, kEnd, kSample, 1e-3);
}

void require_same_grid(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) throw Error({"verify", std::nullopt, "tip history", "compare histories sampled on the same grid"},
                                     "Kane spin-up: tip histories of different lengths");
}

}  // namespace

void mbbt_spin_up(const beam::BeamModel& model, const flexbody::HubSpin& hub, double end_s, double sample_s,
                  const std::function<void(const beam::BeamState&)>& observe) {
  beam::BeamState state = beam::make_state(model);
  beam::DynamicStepper stepper(model, beam::DynamicOptions{});
  const double dt = 0.005;
  const long per_sample = std::lround(sample_s / dt), steps = std::lround(end_s / dt);
  observe(state);
  beam::BeamInput input;
  for (long k = 0; k < steps; ++k) {
    const double t = (static_cast<double>(k) + stepper.input_time_fraction()) * dt;
    input.frame.angular_velocity_rad_s = Vec3(0.0, 0.0, hub.rate(t));
    input.frame.angular_acceleration_rad_s2 = Vec3(0.0, 0.0, hub.acceleration(t));
    stepper.step(input, dt, state);
    if ((k + 1) % per_sample == 0) observe(state);
  }
}

KaneSpinUp kane_spin_up_histories() {
  const flexbody::HubSpin hub = flexbody::kane_spin_up(6.0, beam::benchmarks::kKaneSpinUpTime);
  return {mbbt_tip(hub), rr_tip(hub, 1), rr_tip(hub, 3), beam::benchmarks::kane_rayleigh_ritz_tip(kEnd, kSample, 3)};
}

double max_abs(const std::vector<double>& v) {
  double out = 0.0;
  for (const double x : v) out = std::max(out, std::abs(x));
  return out;
}

double rms_over_max(const std::vector<double>& a, const std::vector<double>& b) {
  require_same_grid(a, b);
  double sq = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) sq += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(sq / static_cast<double>(a.size())) / max_abs(b);
}

double max_abs_difference(const std::vector<double>& a, const std::vector<double>& b) {
  require_same_grid(a, b);
  double diff = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) diff = std::max(diff, std::abs(a[k] - b[k]));
  return diff;
}

}  // namespace fowtsim::driver
