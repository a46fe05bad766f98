#pragma once
// One step of the classical fourth-order Runge–Kutta method, for modules that integrate a small
// explicit ODE inside their own step. Header-only so fixed-size Eigen states stay on the stack.
namespace fowtsim {

// y(t + dt) from y(t) for y' = f(t, y). State: any type with + and scalar *, e.g. Eigen::Vector2d.
template <class State, class Derivative>
State rk4_step(const State& y, double t, double dt, const Derivative& f) {
  const State k1 = f(t, y);
  const State k2 = f(t + 0.5 * dt, State(y + 0.5 * dt * k1));
  const State k3 = f(t + 0.5 * dt, State(y + 0.5 * dt * k2));
  const State k4 = f(t + dt, State(y + dt * k3));
  return y + (dt / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

}  // namespace fowtsim
