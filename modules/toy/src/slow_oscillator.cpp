#include "fowtsim/toy/slow_oscillator.hpp"

#include <Eigen/Core>

#include "fowtsim/core/health.hpp"
#include "fowtsim/core/rk4.hpp"

namespace fowtsim::toy {
namespace {

double acceleration(const SlowOscillator::Params& p, double x, double v, double force) {
  return (force - p.stiffness_N_m * x - p.damping_N_s_m * v) / p.mass_kg;
}

}  // namespace

SlowOscillator::State SlowOscillator::make_state(const Params& p) { return {p.initial_position_m, 0.0}; }

void SlowOscillator::advance(const Params& p, const Input& u, double t, double dt, State& s) {
  const double f = u.interface_loads.force_N.x();
  const auto rhs = [&](double, const Eigen::Vector2d& y) {
    return Eigen::Vector2d(y[1], acceleration(p, y[0], y[1], f));
  };
  const Eigen::Vector2d y = rk4_step(Eigen::Vector2d(s.position_m, s.velocity_m_s), t, dt, rhs);
  s.position_m = y[0];
  s.velocity_m_s = y[1];
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
