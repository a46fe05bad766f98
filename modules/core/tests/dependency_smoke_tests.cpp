// One smoke test per external dependency that core links (STYLE.md: a broken install is obvious).
#include <cmath>

#include <catch2/catch.hpp>
#include <cvode/cvode.h>
#include <fmt/format.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Dense>

TEST_CASE("Eigen solves a small dense system", "[unit][dependencies]") {
  Eigen::Matrix3d a;
  a << 4, 1, 0, 1, 3, 1, 0, 1, 2;
  const Eigen::Vector3d b(1, 2, 3);
  CHECK((a * a.ldlt().solve(b) - b).norm() < 1e-14);
}

TEST_CASE("fmt formats numbers", "[unit][dependencies]") { CHECK(fmt::format("{:.3f}", 1.23456) == "1.235"); }

namespace {
int decay_rhs(sunrealtype, N_Vector y, N_Vector ydot, void*) {
  NV_Ith_S(ydot, 0) = -NV_Ith_S(y, 0);
  return 0;
}
}  // namespace

TEST_CASE("SUNDIALS CVODE integrates y' = -y", "[unit][dependencies]") {
  SUNContext ctx = nullptr;
  REQUIRE(SUNContext_Create(nullptr, &ctx) == 0);
  N_Vector y = N_VNew_Serial(1, ctx);
  NV_Ith_S(y, 0) = 1.0;
  void* mem = CVodeCreate(CV_BDF, ctx);
  REQUIRE(CVodeInit(mem, decay_rhs, 0.0, y) == CV_SUCCESS);
  REQUIRE(CVodeSStolerances(mem, 1e-10, 1e-12) == CV_SUCCESS);
  SUNMatrix jac = SUNDenseMatrix(1, 1, ctx);
  SUNLinearSolver ls = SUNLinSol_Dense(y, jac, ctx);
  REQUIRE(CVodeSetLinearSolver(mem, ls, jac) == CV_SUCCESS);
  sunrealtype t = 0.0;
  REQUIRE(CVode(mem, 2.0, y, &t, CV_NORMAL) == CV_SUCCESS);
  CHECK(NV_Ith_S(y, 0) == Approx(std::exp(-2.0)).epsilon(1e-7));  // rtol 1e-10 requested; 1e-7 covers global error growth
  CVodeFree(&mem);
  SUNLinSolFree(ls);
  SUNMatDestroy(jac);
  N_VDestroy(y);
  SUNContext_Free(&ctx);
}
