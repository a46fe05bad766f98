// Unit checks of the discrete mechanics: the assembled tangent is the exact derivative of the
// assembled loads, internal loads balance, the block-tridiagonal solver is exact.
#include <cmath>

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include "../src/section_mechanics.hpp"
#include "fowtsim/beam/block_tridiagonal.hpp"
#include "fowtsim/beam/linear_system.hpp"
#include "fowtsim/beam/benchmarks.hpp"
#include "fowtsim/beam/modal.hpp"
#include "fowtsim/beam/solvers.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation_vector.hpp"
#include "test_beams.hpp"

using namespace fowtsim;
using namespace fowtsim::beam;

namespace {

// A deformed configuration of the general beam: every node moved and turned by smooth,
// finite amounts (up to ~0.3 m and ~0.4 rad).
BeamState deformed(const BeamModel& model) {
  BeamState s = make_state(model);
  for (int n = 0; n < model.node_count(); ++n) {
    const double t = model.nodes[n].s_m / model.length_m;
    s.position_m[n] += Vec3(0.3 * t * t, -0.2 * t, 0.05 * std::sin(3 * t));
    s.orientation[n] = rotation_matrix(Vec3(0.4 * t, -0.3 * t * t, 0.2 * std::sin(2 * t))) * s.orientation[n];
  }
  return s;
}

BeamInput loaded_input(const BeamModel& model) {
  BeamInput in;
  in.frame.angular_velocity_rad_s = Vec3(0.3, 1.1, -0.4);
  in.frame.angular_acceleration_rad_s2 = Vec3(0.2, -0.5, 0.7);
  in.frame.acceleration_m_s2 = Vec3(0.5, -1.0, 2.0);
  in.frame.gravity_m_s2 = Vec3(0.0, -9.81, 0.0);
  in.node_loads.assign(model.node_count(), (Vec6() << 100, -50, 20, 10, 5, -3).finished());
  in.tip_load << 300, 200, -100, 40, -20, 10;
  return in;
}

// The general beam carrying a fluid, every flow term present: flow, pressure given at the root,
// wall friction; `seed_flux` selects the seed's momentum flux (internal_flow.hpp).
BeamModel general_pipe(int segments, bool seed_flux) {
  BeamModel model = discretise(testing::general_beam(), segments);
  model.flow = InternalFlow{12.0, 0.012, 7.0, 30.0, 2e5, false, seed_flux};
  return model;
}

// The general beam or pipe of a tangent test: variant 0 the beam, 1 the pipe, 2 the pipe with the
// seed's flux, 3 the beam pinned at the root and clamped at the tip, 4 the pipe clamped at the root
// and pinned at the tip.
BeamModel tangent_test_model(int variant, int segments, double mass_damping = 0.0) {
  BeamDefinition def = testing::general_beam();
  def.mass_damping_1_s = mass_damping;
  if (variant == 3) {
    def.root_end = EndCondition::pinned;
    def.tip_end = EndCondition::clamped;
  }
  if (variant == 4) def.tip_end = EndCondition::pinned;
  BeamModel model = discretise(def, segments);
  if (variant == 1 || variant == 2 || variant == 4) model.flow = general_pipe(segments, variant == 2).flow;
  if (variant == 5) {  // a pipe held at both ends in water with a current: buoyancy, added mass, drag
    def.tip_end = EndCondition::clamped;
    model = discretise(def, segments);
    model.flow = general_pipe(segments, false).flow;
    model.water = SurroundingWater{.outer_diameter_m = 0.05, .added_mass_coefficient = 0.8, .drag_coefficient = 1.2,
                                   .surface_z_m = 1e3, .current_m_s = Vec3(0.4, -0.2, 0.1)};
  }
  return model;
}

// Apply increment q (one DOF perturbed by h) to a copy of the state.
BeamState perturbed(const BeamState& s, int dof, double h) {
  BeamState p = s;
  VecX q = VecX::Zero(6 * static_cast<int>(s.position_m.size()));
  q[dof] = h;
  update_base(q, p);
  return p;
}

}  // namespace

TEST_CASE("block-tridiagonal factor and solve match a dense LU", "[unit][beam]") {
  const int n = 7;
  BlockTridiagonal a(n);
  MatX dense = MatX::Zero(6 * n, 6 * n);
  for (int i = 0; i < n; ++i) {
    a.diag(i) = Mat6::Random() + 12.0 * Mat6::Identity();
    dense.block<6, 6>(6 * i, 6 * i) = a.diag(i);
    if (i + 1 < n) {
      a.upper(i) = Mat6::Random();
      a.lower(i) = Mat6::Random();
      dense.block<6, 6>(6 * i, 6 * i + 6) = a.upper(i);
      dense.block<6, 6>(6 * i + 6, 6 * i) = a.lower(i);
    }
  }
  const VecX b = VecX::Random(6 * n);
  VecX y(6 * n);
  a.multiply(b, y);
  CHECK((y - dense * b).norm() < 1e-12 * y.norm());  // same products, rounding only
  VecX x = b;
  REQUIRE(a.factor());
  a.solve_in_place(x);
  CHECK((x - dense.lu().solve(b)).norm() < 1e-12 * x.norm());  // well-conditioned: rounding only
  // Two right-hand sides at once give each one's solution (the same products, rounding only).
  const VecX c = VecX::Random(6 * n);
  VecX x1 = b, x2 = c, xc = c;
  a.solve_in_place(x1, x2);
  a.solve_in_place(xc);
  CHECK((x1 - x).norm() < 1e-14 * x.norm());
  CHECK((x2 - xc).norm() < 1e-14 * xc.norm());
}

TEST_CASE("section loads balance in force and moment and vanish under rigid motion",
          "[unit][beam]") {
  const BeamModel model = discretise(testing::general_beam(), 6);
  const BeamState s = deformed(model);
  const SectionModel& sec = model.sections[3];
  const NodePose a{s.position_m[2], s.orientation[2]}, b{s.position_m[3], s.orientation[3]};
  const Vec12 f = section_loads(sec, a, b);
  // Total force and moment about the origin: f_a + f_b = 0, x_a × f_a + m_a + x_b × f_b + m_b = 0.
  const double scale = f.norm();
  CHECK((f.segment<3>(0) + f.segment<3>(6)).norm() < 1e-12 * scale);
  CHECK((a.position_m.cross(f.segment<3>(0)) + f.segment<3>(3) + b.position_m.cross(f.segment<3>(6)) +
         f.segment<3>(9)).norm() < 1e-11 * scale);
  // Undeformed pair, then the same pair moved rigidly: no load (strain measures are objective).
  const BeamState s0 = make_state(model);
  const Mat3 rot = rotation_matrix(Vec3(0.7, -1.2, 2.0));
  const Vec3 shift(3.0, -1.0, 2.0);
  const NodePose a0{rot * s0.position_m[2] + shift, rot * s0.orientation[2]};
  const NodePose b0{rot * s0.position_m[3] + shift, rot * s0.orientation[3]};
  CHECK(section_loads(sec, a0, b0).norm() < 1e-6);  // vs loads ~1e5 N when deformed
}

TEST_CASE("section stiffness is the exact derivative of the section loads", "[unit][beam]") {
  const BeamModel model = discretise(testing::general_beam(), 5);
  const BeamState s = deformed(model);
  for (int j : {0, 2, 4}) {
    const SectionModel& sec = model.sections[j];
    const int ia = sec.inboard, ib = sec.outboard;
    auto pose = [&](const BeamState& st, int n) {
      return n < 0 ? NodePose{model.root_position_m, model.root_orientation}
                   : NodePose{st.position_m[n], st.orientation[n]};
    };
    SectionLinearization lin;
    linearize_section(sec, pose(s, ia), pose(s, ib), lin);
    Mat12 stiffness;
    section_tangent(lin, sec.stiffness, 1.0, stiffness);
    const double h = 1e-6;
    double worst = 0.0;
    for (int side = 0; side < 2; ++side) {
      const int node = side == 0 ? ia : ib;
      if (node < 0) continue;
      for (int k = 0; k < 6; ++k) {
        const BeamState sp = perturbed(s, 6 * node + k, h), sm = perturbed(s, 6 * node + k, -h);
        const Vec12 fd = -(section_loads(sec, pose(sp, ia), pose(sp, ib)) -
                           section_loads(sec, pose(sm, ia), pose(sm, ib))) / (2 * h);
        worst = std::max(worst, (fd - stiffness.col(6 * side + k)).norm() / stiffness.norm());
      }
    }
    // Central differences at h = 1e-6: truncation ~h² and rounding ~ε/h ≈ 1e-10 relative.
    CHECK(worst < 1e-7);
  }
}

TEST_CASE("assembled static stiffness is the derivative of the assembled loads, frame terms "
          "included", "[unit][beam]") {
  // A pipe's pressure follows the base explicitly (seed §3.4.2) and is left out of K: its pipe
  // variant runs without frame motion, where the pressure does not depend on the configuration.
  const int variant = GENERATE(0, 1, 2, 3, 4);
  const BeamModel model = tangent_test_model(variant, 5);
  BeamInput in = loaded_input(model);
  if (model.flow) in.frame = FrameKinematics{};
  const BeamState s = deformed(model);
  LinearizedBeam sys, sp, sm;
  linearize(model, in, s, Inertia::static_only, sys);
  const int dofs = model.dof_count();
  const MatX k_dense = sys.stiffness.dense();
  const double h = 1e-6;
  MatX fd(dofs, dofs);
  for (int c = 0; c < dofs; ++c) {
    linearize(model, in, perturbed(s, c, h), Inertia::static_only, sp);
    linearize(model, in, perturbed(s, c, -h), Inertia::static_only, sm);
    fd.col(c) = -(sp.rhs - sm.rhs) / (2 * h);
  }
  // Same bound as the section check: central-difference error only.
  CHECK((fd - k_dense).norm() < 1e-7 * k_dense.norm());
}

TEST_CASE("natural frequencies of a slender uniform cantilever match Euler-Bernoulli",
          "[verification][beam]") {
  // Steel strip 3.31 mm square, 1 m: f_k = (β_k L)² / (2π) √(EI / m L⁴), β_1 L = 1.87510,
  // β_2 L = 4.69409. Slender (L/h = 300): shear and rotary inertia shift f_2 by < 0.01 %.
  const BeamModel model = discretise(benchmarks::steel_strip(), 100);
  const double ei = 200e9 * std::pow(0.00331, 4) / 12.0, m = 7850.0 * 0.00331 * 0.00331;
  const double scale = std::sqrt(ei / m) / (2.0 * 3.14159265358979323846);
  const std::vector<double> f = natural_frequencies_hz(model, BeamInput{}, make_state(model), 4);
  REQUIRE(f.size() == 4);
  // Bending about either axis gives the same pair (square section): f[0] ≈ f[1], f[2] ≈ f[3].
  // Second order: (1/N)² = 1e-4 at N = 100 bounds the discretisation error; measured 1.9e-5.
  CHECK(std::abs(f[0] / (1.87510 * 1.87510 * scale) - 1.0) < 1e-4);
  CHECK(std::abs(f[2] / (4.69409 * 4.69409 * scale) - 1.0) < 1e-4);
}

TEST_CASE("a key-point line that turns back along z stops at discretisation", "[unit][beam]") {
  // BeamDyn's frame rule needs the tangent to advance along z; a hook-shaped line must not run
  // with NaN frames.
  BeamDefinition def{ReferenceLine::through_key_points({Vec3(0, 0, 0), Vec3(0, 0, 5), Vec3(3, 0, 6), Vec3(6, 0, 4)},
                                                       {0.0, 0.0, 0.0, 0.0}),
                     {}};
  def.stations = {benchmarks::uniform_station(0.0, Vec6::Ones(), 1.0, Vec3::Ones()),
                  benchmarks::uniform_station(1.0, Vec6::Ones(), 1.0, Vec3::Ones())};
  CHECK_THROWS_AS(discretise(def, 20), InputError);
}

TEST_CASE("the one-pass step matrix and the matrix-free residual equal the assembled system",
          "[unit][beam]") {
  // assemble_step_matrix builds m M + c C + k K without forming M, C, K apart, and step_residual
  // applies r − M a − C w_c − K w_k as vector formulas; both must agree with linearize to rounding.
  const int variant = GENERATE(0, 1, 2, 3, 4, 5);  // tangent_test_model (5: in water)
  const BeamModel model = tangent_test_model(variant, 6, 0.02);
  const BeamInput in = loaded_input(model);
  BeamState s = deformed(model);
  for (int n = 0; n < model.node_count(); ++n) s.velocity[n] << 0.1 * n, -0.3, 0.2, 0.01, 0.0, -0.02;  // the drag's base
  LinearizedBeam sys;
  linearize(model, in, s, Inertia::included, sys);

  const int dofs = model.dof_count();
  VecX w_c(dofs), w_k(dofs), acc(dofs);
  for (int i = 0; i < dofs; ++i) {
    w_c[i] = std::sin(0.7 * i);
    w_k[i] = 1e-3 * std::cos(1.3 * i);
    acc[i] = std::sin(2.1 * i + 0.4);
  }
  const StepWeights weights{0.8, 0.3, 0.02};
  BlockTridiagonal lhs(model.node_count());
  assemble_step_matrix(model, in, s, weights, lhs);
  VecX residual(dofs);
  step_residual(model, in, s, w_c, w_k, acc, residual);

  MatX mass = MatX::Zero(dofs, dofs);
  for (int i = 0; i < model.node_count(); ++i) mass.block<6, 6>(6 * i, 6 * i) = sys.mass[i];
  const MatX a = weights.mass * mass + weights.damping * sys.damping.dense() + weights.stiffness * sys.stiffness.dense();
  const VecX b = sys.rhs - mass * acc - sys.damping.dense() * w_c - sys.stiffness.dense() * w_k;
  // Same terms summed in another order: rounding only (entries up to ~1e7).
  CHECK((lhs.dense() - a).norm() < 1e-12 * a.norm());
  CHECK((residual - b).norm() < 1e-12 * b.norm());
}
