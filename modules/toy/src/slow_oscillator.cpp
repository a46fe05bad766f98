#include "fowtsim/toy/slow_oscillator.hpp"

#include "fowtsim/core/health.hpp"

namespace fowtsim::toy {
namespace {

double acceleration(const SlowOscillator::Params& p, double x, double v, double force) {
  return (force - p.stiffness_N_m * x - p.damping_N_s_m * v) / p.mass_kg;
}

}  // namespace

SlowOscillator::State SlowOscillator::make_state(const Params& p) { return {p.initial_position_m, 0.0}; }

void SlowOscillator::advance(const Params& p, const Input& u, double t, double dt, State& s) {
  const double f = u.interface_loads.force_N.x();
  const double x = s.position_m, v = s.velocity_m_s;
  const double k1x = v, k1v = acceleration(p, x, v, f);
  const double k2x = v + 0.5 * dt * k1v, k2v = acceleration(p, x + 0.5 * dt * k1x, k2x, f);
  const double k3x = v + 0.5 * dt * k2v, k3v = acceleration(p, x + 0.5 * dt * k2x, k3x, f);
  const double k4x = v + dt * k3v, k4v = acceleration(p, x + dt * k3x, k4x, f);
  s.position_m = x + dt / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
  s.velocity_m_s = v + dt / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
  check_bounded("toy.slow", "X (slow position)", s.position_m, p.divergence_limit_m, t + dt);
  check_finite("toy.slow", "Xdot (slow velocity)", s.velocity_m_s, t + dt);
}

SlowOscillator::Output SlowOscillator::outputs(const Params& p, const Input& u, const State& s) {
  Output out;
  const double f = u.interface_loads.force_N.x();
  out.attachment.position_m = {s.position_m, 0.0, 0.0};
  out.attachment.velocity_m_s = {s.velocity_m_s, 0.0, 0.0};
  out.attachment.acceleration_m_s2 = {acceleration(p, s.position_m, s.velocity_m_s, f), 0.0, 0.0};
  out.interface_force_N = f;
  return out;
}

std::vector<ChannelInfo> SlowOscillator::channels(const Params&) {
  return {{"ToySlowPos", "m", "slow mass position X along g-x", "toy.slow"},
          {"ToySlowVel", "m/s", "slow mass velocity", "toy.slow"},
          {"ToyIfcForce", "N", "averaged interface force applied to the slow mass", "toy.slow"}};
}

}  // namespace fowtsim::toy
