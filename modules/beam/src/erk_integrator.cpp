#include "erk_integrator.hpp"

#include <arkode/arkode_erkstep.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::beam {
namespace {

int ode_rhs(realtype t, N_Vector y, N_Vector ydot, void* self) {
  return DynamicStepper::Erk::rhs(t, y, ydot, self);
}

[[noreturn]] void fail(const char* what) {
  throw NumericalError({"beam.erk", std::nullopt, "ARKODE", "reduce the beam time step"}, what);
}

}  // namespace

DynamicStepper::Erk::Erk(int n, double rtol, double atol) : dofs(n), force(VecX::Zero(n)) {
  SUNContext ctx = nullptr;
  if (SUNContext_Create(nullptr, &ctx) != 0) fail("SUNContext_Create failed");
  context = ctx;
  N_Vector v = N_VNew_Serial(2 * n, ctx);
  N_VConst(0.0, v);
  y = v;
  memory = ERKStepCreate(ode_rhs, 0.0, v, ctx);
  if (!memory) fail("ERKStepCreate failed");
  ERKStepSetTableNum(memory, ARKODE_DORMAND_PRINCE_7_4_5);
  ERKStepSStolerances(memory, rtol, atol);
  ERKStepSetUserData(memory, this);
  ERKStepSetMaxNumSteps(memory, 100000);
  mass_lu.resize(n / 6);
}

DynamicStepper::Erk::~Erk() {
  ERKStepFree(&memory);
  N_VDestroy(static_cast<N_Vector>(y));
  SUNContext ctx = static_cast<SUNContext>(context);
  SUNContext_Free(&ctx);
}

int DynamicStepper::Erk::rhs(double, void* yv, void* ydotv, void* selfv) {
  auto* self = static_cast<Erk*>(selfv);
  const int n = self->dofs;
  Eigen::Map<const VecX> state(N_VGetArrayPointer(static_cast<N_Vector>(yv)), 2 * n);
  Eigen::Map<VecX> rate(N_VGetArrayPointer(static_cast<N_Vector>(ydotv)), 2 * n);
  const LinearizedBeam& sys = *self->system;
  // force = r − C v − K q
  self->force = sys.rhs;
  const int blocks = n / 6;
  for (int i = 0; i < blocks; ++i) {
    Vec6 acc = sys.damping.diag(i) * state.segment<6>(n + 6 * i) + sys.stiffness.diag(i) * state.segment<6>(6 * i);
    if (i > 0)
      acc += sys.damping.lower(i - 1) * state.segment<6>(n + 6 * (i - 1)) +
             sys.stiffness.lower(i - 1) * state.segment<6>(6 * (i - 1));
    if (i + 1 < blocks)
      acc += sys.damping.upper(i) * state.segment<6>(n + 6 * (i + 1)) +
             sys.stiffness.upper(i) * state.segment<6>(6 * (i + 1));
    self->force.segment<6>(6 * i) -= acc;
  }
  rate.head(n) = state.tail(n);
  for (int i = 0; i < blocks; ++i) rate.segment<6>(n + 6 * i) = self->mass_lu[i].solve(Vec6(self->force.segment<6>(6 * i)));
  return 0;
}

void DynamicStepper::Erk::integrate(const LinearizedBeam& sys, double dt, const VecX& v0, VecX& q,
                                    VecX& v) {
  system = &sys;
  for (std::size_t i = 0; i < mass_lu.size(); ++i) mass_lu[i].compute(sys.mass[i]);
  N_Vector yv = static_cast<N_Vector>(y);
  Eigen::Map<VecX> state(N_VGetArrayPointer(yv), 2 * dofs);
  state.head(dofs).setZero();
  state.tail(dofs) = v0;
  if (ERKStepReInit(memory, ode_rhs, 0.0, yv) != ARK_SUCCESS) fail("ERKStepReInit failed");
  ERKStepSetStopTime(memory, dt);
  realtype t_reached = 0.0;
  if (ERKStepEvolve(memory, dt, yv, &t_reached, ARK_NORMAL) < 0) fail("ERKStepEvolve failed");
  q = state.head(dofs);
  v = state.tail(dofs);
}

}  // namespace fowtsim::beam
