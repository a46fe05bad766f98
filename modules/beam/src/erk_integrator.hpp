#pragma once
// The seed's integrator of the locally linear system (§2.5: MATLAB ode45, RelTol 1e-6):
// SUNDIALS ARKODE's explicit Dormand–Prince 5(4) pair with adaptive internal steps. The ODE
//   q̇ = v,  v̇ = M⁻¹ (r − C v − K q),  q(0) = 0, v(0) = v0
// is integrated over one beam step. M is block diagonal: its 6×6 blocks are factored once per
// step. The ARKODE memory lives as long as the stepper and is re-initialised per step.
#include <vector>

#include <Eigen/LU>

#include "fowtsim/beam/linear_system.hpp"
#include "fowtsim/beam/solvers.hpp"

namespace fowtsim::beam {

struct DynamicStepper::Erk {
  Erk(int dofs, double rtol, double atol);
  ~Erk();
  Erk(const Erk&) = delete;
  Erk& operator=(const Erk&) = delete;

  void integrate(const LinearizedBeam& system, double dt, const VecX& v0, VecX& q, VecX& v);

  static int rhs(double t, void* y, void* ydot, void* self);  // N_Vector in, N_Vector out

  int dofs;
  void* context = nullptr;  // SUNContext
  void* y = nullptr;        // N_Vector of [q; v]
  void* memory = nullptr;   // ARKODE ERKStep memory
  const LinearizedBeam* system = nullptr;
  std::vector<Eigen::PartialPivLU<Mat6>> mass_lu;
  VecX force;
};

}  // namespace fowtsim::beam
