#pragma once
// Exact finite rotations by rotation vectors φ = φ n (angle φ about unit axis n): the exponential
// map of SO(3), its logarithm, and the Jacobians that relate a perturbation of φ to a
// perturbation of the rotation. The piecewise-linear beam (seed 000 §2.4.3) composes every
// incremental rotation exactly with these instead of I + θ̃ (eq. 2.67), so the base
// configuration stays a rotation after any number of steps.
#include "fowtsim/core/types.hpp"

namespace fowtsim {

// exp(φ̃) = I + sin φ/φ φ̃ + (1 − cos φ)/φ² φ̃² (Rodrigues). Series near φ = 0.
Mat3 rotation_matrix(const Vec3& phi_rad);

// log: the rotation vector of r with |φ| ≤ π. Accurate near 0 and near π.
Vec3 rotation_vector(const Mat3& r);

// Right Jacobian J_r(φ): exp((φ + δφ)~) ≈ exp(φ̃) exp((J_r(φ) δφ)~) to first order.
Mat3 right_jacobian(const Vec3& phi_rad);

// Its inverse: log(exp(φ̃) exp(ε̃)) ≈ φ + J_r(φ)⁻¹ ε. Valid for |φ| < 2π.
Mat3 right_jacobian_inverse(const Vec3& phi_rad);

// Wiener–Milenkovic parameters c = 4 tan(φ/4) n of a rotation (BeamDyn's TipRD channels).
Vec3 wiener_milenkovic(const Mat3& r);

}  // namespace fowtsim
