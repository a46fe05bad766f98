#pragma once
// Forced response of a linear Rayleigh–Ritz model M q̈ + D q̇ + K q = f sin(Ω t) from rest (the seed's
// Sec. 5.3 test), and the one-DOF analytic transient it is compared with.
#include <Eigen/Dense>
#include <vector>

namespace fowtsim::flexbody {

// Individual stiffness-proportional damping (seed Sec. 2.3): D = diag(β_j K_jj), β_j = 2ζ/ω_j,
// ω_j = sqrt(K_jj/M_jj) — for shapes that are modes (M, K diagonal), every mode has damping ratio ζ.
Eigen::MatrixXd modal_stiffness_damping(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, double zeta);

// Output y = cᵀ q at t = k·sample_s, k = 0 … round(end_s/sample_s), from q = q̇ = 0, by classical RK4
// with ceil(sample_s/max_step_s) equal steps per sample (the seed's Sec. 2.3 scheme).
// Throws InputError on inconsistent sizes or non-positive times.
std::vector<double> harmonic_response(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D,
                                      const Eigen::MatrixXd& K, const Eigen::VectorXd& force_amplitude,
                                      double forcing_frequency, const Eigen::VectorXd& output, double end_s,
                                      double sample_s, double max_step_s);

// x(t) of ẍ + 2ζω ẋ + ω² x = ω² x_st sin(Ω t), x(0) = ẋ(0) = 0 (ζ < 1):
//   x = A e^(−ζωt) sin(ω_d t + ψ) + H₀ sin(Ω t − φ),  ω_d = ω sqrt(1 − ζ²),
//   H₀ = x_st / sqrt((1 − r²)² + (2ζr)²),  φ = atan2(2ζr, 1 − r²),  r = Ω/ω,
// A and ψ from the initial conditions: A sin ψ = H₀ sin φ, A ω_d cos ψ = H₀ (ζω sin φ − Ω cos φ).
struct SingleDofTransient {
  double omega, zeta, forcing, static_amplitude;
  double H0, phi, A, psi;  // derived
  SingleDofTransient(double omega, double zeta, double forcing, double static_amplitude);
  double operator()(double t) const;
};

}  // namespace fowtsim::flexbody
