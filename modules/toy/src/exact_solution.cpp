#include "fowtsim/toy/exact_solution.hpp"

#include <Eigen/Eigenvalues>
#include <unsupported/Eigen/MatrixFunctions>



namespace fowtsim::toy {

ExactSolution::ExactSolution(const SlowOscillator::Params& s, const FastOscillator::Params& f) {
  // Equations in [X, q] (q relative): M Ẍ = −K X − C Ẋ + k q + c q̇ ;  q̈ = −(k q + c q̇)/m − Ẍ.
  const double mr = s.mass_kg, kr = s.stiffness_N_m, cr = s.damping_N_s_m;
  const double m = f.mass_kg, k = f.stiffness_N_m, c = f.damping_N_s_m;
  a_.setZero();
  a_(0, 1) = 1.0;
  a_(1, 0) = -kr / mr;
  a_(1, 1) = -cr / mr;
  a_(1, 2) = k / mr;
  a_(1, 3) = c / mr;
  a_(2, 3) = 1.0;
  a_.row(3) = -a_.row(1);
  a_(3, 2) -= k / m;
  a_(3, 3) -= c / m;
  z0_ << s.initial_position_m, 0.0, f.initial_position_m, 0.0;
  // Mass and stiffness in [X, q]: kinetic energy ½M Ẋ² + ½m (Ẋ+q̇)².
  mass_ << mr + m, m, m, m;
  stiffness_ << kr, 0.0, 0.0, k;
}

Eigen::Vector4d ExactSolution::state_at(double time_s) const {
  const Eigen::Matrix4d at = a_ * time_s;
  return at.exp() * z0_;
}

Eigen::Vector2d ExactSolution::natural_frequencies_rad_s() const {
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> solver(stiffness_, mass_);
  return solver.eigenvalues().cwiseSqrt();
}

double mechanical_energy(const SlowOscillator::Params& s, const FastOscillator::Params& f,
                         const Eigen::Vector4d& z) {
  const double v_abs = z[1] + z[3];
  return 0.5 * (s.stiffness_N_m * z[0] * z[0] + s.mass_kg * z[1] * z[1] + f.stiffness_N_m * z[2] * z[2] +
                f.mass_kg * v_abs * v_abs);
}

}  // namespace fowtsim::toy
