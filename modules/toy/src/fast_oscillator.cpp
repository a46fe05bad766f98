#include "fowtsim/toy/fast_oscillator.hpp"

#include "fowtsim/core/health.hpp"

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
  const double am = 0.5 * (a0 + a1);  // linear frame acceleration: value at the midpoint
  const double q = s.position_m, v = s.velocity_m_s;
  const double k1q = v, k1v = relative_acceleration(p, q, v, a0);
  const double k2q = v + 0.5 * dt * k1v, k2v = relative_acceleration(p, q + 0.5 * dt * k1q, k2q, am);
  const double k3q = v + 0.5 * dt * k2v, k3v = relative_acceleration(p, q + 0.5 * dt * k2q, k3q, am);
  const double k4q = v + dt * k3v, k4v = relative_acceleration(p, q + dt * k3q, k4q, a1);
  s.position_m = q + dt / 6.0 * (k1q + 2 * k2q + 2 * k3q + k4q);
  s.velocity_m_s = v + dt / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
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
