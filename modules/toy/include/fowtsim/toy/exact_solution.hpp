#pragma once
// Exact solution of the coupled toy problem: the four-state linear system z = [X, Ẋ, q, q̇]
// integrated by the matrix exponential, z(t) = exp(A t) z(0).
#include <Eigen/Core>

#include "fowtsim/toy/fast_oscillator.hpp"
#include "fowtsim/toy/slow_oscillator.hpp"

namespace fowtsim::toy {

class ExactSolution {
 public:
  ExactSolution(const SlowOscillator::Params& slow, const FastOscillator::Params& fast);

  // State [X, Ẋ, q, q̇] at time t [s] (SI units).
  Eigen::Vector4d state_at(double time_s) const;

  // Undamped natural frequencies of the coupled system [rad/s], ascending.
  Eigen::Vector2d natural_frequencies_rad_s() const;

  const Eigen::Matrix4d& system_matrix() const { return a_; }

 private:
  Eigen::Matrix4d a_;   // ż = A z
  Eigen::Vector4d z0_;  // initial state
  Eigen::Matrix2d mass_, stiffness_;  // in coordinates [X, q]: for the natural frequencies
};

// Total mechanical energy of the toy system [J] (used for stability detection).
double mechanical_energy(const SlowOscillator::Params& slow, const FastOscillator::Params& fast,
                         const Eigen::Vector4d& z);

}  // namespace fowtsim::toy
