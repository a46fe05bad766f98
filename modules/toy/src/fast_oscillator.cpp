#include "fowtsim/toy/fast_oscillator.hpp"

#include <Eigen/Core>

#include "fowtsim/core/health.hpp"
#include "fowtsim/core/rk4.hpp"

namespace fowtsim::toy {
namespace {

double relative_acceleration(const FastOscillator::Params& p, double q, double v, double frame_acc) {
  return -(p.stiffness_N_m * q + p.damping_N_s_m * v) / p.mass_kg - frame_acc;
}

}  // namespace

FastOscillator::State FastOscillator::make_state(const Params& p) { return {p.initial_position_m, 0.0}; }

void FastOscillator::advance(const Params& p, const Input& u, double t, double dt, State& s) {
  const double a0 = u.frame_begin.acceleration_m_s2.x();
  const double a1 = u.frame_end.acceleration_m_s2.x();
  // Frame acceleration linear over the step, between the two snapshots the driver hands in.
  const auto rhs = [&](double time, const Eigen::Vector2d& y) {
    const double frame_acc = a0 + (time - t) / dt * (a1 - a0);
    return Eigen::Vector2d(y[1], relative_acceleration(p, y[0], y[1], frame_acc));
  };
  const Eigen::Vector2d y = rk4_step(Eigen::Vector2d(s.position_m, s.velocity_m_s), t, dt, rhs);
  s.position_m = y[0];
  s.velocity_m_s = y[1];
  check_bounded("toy.fast", "q (fast relative position)", s.position_m, p.divergence_limit_m, t + dt);
  check_finite("toy.fast", "qdot (fast relative velocity)", s.velocity_m_s, t + dt);
}

FastOscillator::Output FastOscillator::outputs(const Params& p, const Input& u, const State& s) {
  Output out;
  out.root_loads.force_N = {p.stiffness_N_m * s.position_m + p.damping_N_s_m * s.velocity_m_s, 0.0, 0.0};
  out.root_loads.point_m = u.frame_end.position_m;
  return out;
}

std::vector<ChannelInfo> FastOscillator::channels(const Params&) {
  return {{"ToyFastRelPos", "m", "fast mass position q relative to the attachment point", "toy.fast"},
          {"ToyFastRelVel", "m/s", "fast mass velocity relative to the attachment point", "toy.fast"},
          {"ToyRootForce", "N", "instantaneous interface force of the fast mass on the slow mass", "toy.fast"}};
}

}  // namespace fowtsim::toy
