#pragma once
// A prescribed rotation of a body's root about an axis normal to its bending plane: angular speed
// Ω(t) [rad/s] and acceleration α(t) = dΩ/dt [rad/s²] (the hub of the seed's Sec. 5.2).
#include <functional>

namespace fowtsim::flexbody {

struct HubSpin {
  std::function<double(double t)> rate;          // Ω(t) [rad/s]
  std::function<double(double t)> acceleration;  // α(t) [rad/s²]
};

// Kane, Ryan & Banerjee (1987), the seed's Sec. 5.2 "driver experiment", from rest at t = 0:
//   α = (Ω_s/T_s)(1 − cos(2πt/T_s)),  Ω = (Ω_s/T_s)(t − (T_s/2π) sin(2πt/T_s))  for 0 ≤ t < T_s,
//   α = 0, Ω = Ω_s afterwards (Ω and α are both continuous at T_s).
// The seed's values, θ̈ = (2/5)(1 − cos(πt/7.5)) up to 15 s, are Ω_s = 6 rad/s, T_s = 15 s.
// Throws InputError unless T_s > 0.
HubSpin kane_spin_up(double final_rate, double spin_up_time);

}  // namespace fowtsim::flexbody
