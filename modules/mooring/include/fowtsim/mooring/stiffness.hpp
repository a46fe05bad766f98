#pragma once
// Linearised 6×6 mooring stiffness of the platform at a pose: K = −∂[F; M]/∂[δx; δθ], with F, M the
// total mooring force and moment about the platform reference point (inertial frame g), δx a
// translation of the reference point and δθ a small rotation about the inertial axes applied on
// the left (T_gb → exp(δθ̃) T_gb). At zero orientation δθ equals the increments of OpenFAST's
// platform roll, pitch and yaw, so K compares one to one with published OC3 matrices.
#include "fowtsim/core/types.hpp"
#include "fowtsim/mooring/quasi_static_mooring.hpp"

namespace fowtsim::mooring {

// Analytic: each line's converged 2-D stiffness ∂(H, V)/∂(X, Z) (the inverse of the span
// Jacobian, available from the Newton solve at no extra cost) is rotated into 3-D and carried to
// the reference point, including the load-stiffness term −F̃ r̃ of the fairlead forces and the
// yaw spring. One solve per line, exact to rounding, no step size to choose, and no noise where a
// finite difference would straddle a change of branch (touchdown ↔ suspended, slack ↔ taut).
// Exactly vertical lines with H = 0 get their lateral (pendulum) stiffness from the X → 0 limit
// of the span equations when lifted off the seabed, and none when they end in a slack heap.
Mat6 linearized_stiffness(const MooringParams& p, const QuasiStaticMooring::Input& u,
                          const QuasiStaticMooring::State& s);

// The same matrix by central differences of the full nonlinear solution with steps
// translation_step_m and rotation_step_rad — the independent check of the analytic one.
Mat6 linearized_stiffness_finite_difference(const MooringParams& p, const QuasiStaticMooring::Input& u,
                                            const QuasiStaticMooring::State& s, double translation_step_m = 1e-3,
                                            double rotation_step_rad = 1e-5);

}  // namespace fowtsim::mooring
