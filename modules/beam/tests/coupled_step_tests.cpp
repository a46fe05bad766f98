// The two-half step (DynamicStepper::prepare/finish) through which a partner solves for a frame
// acceleration together with the beam (the rotor spin with the blades, DESIGN.md §4), the
// residual's frame-acceleration derivative it rests on, and the step's atomicity and copyability.
#include <cmath>

#include <Eigen/Geometry>

#include <catch2/catch.hpp>

#include "../src/section_mechanics.hpp"

#include "fowtsim/beam/beam_outputs.hpp"
#include "fowtsim/beam/linear_system.hpp"
#include "fowtsim/beam/rotating_benchmarks.hpp"
#include "fowtsim/beam/solvers.hpp"
#include "fowtsim/core/error.hpp"

using namespace fowtsim;
using namespace fowtsim::beam;

namespace {

// Kane's beam mid-spin-up, bent and moving, so every term of the residual is active.
struct Bent {
  BeamModel model = discretise(benchmarks::kane_beam(), 12);
  BeamState state = make_state(model);
  Bent() {
    DynamicStepper stepper(model, DynamicOptions{});
    BeamInput input;
    for (int k = 0; k < 400; ++k) {
      input.frame = benchmarks::kane_frame((k + 1) * 0.01);
      input.frame.gravity_m_s2 = Vec3(0.3, -9.0, 2.0);
      stepper.step(input, 0.01, state);
    }
  }
};

BeamInput input_at(double t) {
  BeamInput input;
  input.frame = benchmarks::kane_frame(t);
  input.frame.gravity_m_s2 = Vec3(0.3, -9.0, 2.0);
  input.frame.acceleration_m_s2 = Vec3(0.1, 0.2, -0.3);
  return input;
}

double max_abs_diff(const BeamState& a, const BeamState& b) {
  double d = 0.0;
  for (std::size_t n = 0; n < a.position_m.size(); ++n) {
    d = std::max(d, (a.position_m[n] - b.position_m[n]).cwiseAbs().maxCoeff());
    d = std::max(d, (a.orientation[n] - b.orientation[n]).cwiseAbs().maxCoeff());
    d = std::max(d, (a.velocity[n] - b.velocity[n]).cwiseAbs().maxCoeff());
  }
  return d;
}

}  // namespace

TEST_CASE("the residual is affine in the frame acceleration with frame_acceleration_load as slope", "[unit][beam]") {
  Bent b;
  const int dofs = b.model.dof_count();
  VecX w_c = VecX::Constant(dofs, 0.01), w_k = VecX::Constant(dofs, 1e-4), a = VecX::Constant(dofs, 0.2);
  for (int i = 0; i < dofs; ++i) w_k[i] *= std::sin(1.3 * i);
  const Vec3 da(0.7, -0.2, 0.4), dw(0.05, 0.3, -1.1);
  BeamInput in = input_at(4.0);
  VecX r0(dofs), r1(dofs), slope(dofs);
  step_residual(b.model, in, b.state, w_c, w_k, a, r0);
  in.frame.acceleration_m_s2 += 2.0 * da;
  in.frame.angular_acceleration_rad_s2 += 2.0 * dw;
  step_residual(b.model, in, b.state, w_c, w_k, a, r1);
  frame_acceleration_load(b.model, b.state, w_k, da, dw, slope);
  // Exact to rounding: both sides are the same sums; 1e-12 of the residual scale.
  CHECK((r1 - r0 - 2.0 * slope).cwiseAbs().maxCoeff() <= 1e-12 * r1.cwiseAbs().maxCoeff());
}

TEST_CASE("a step in two halves equals a plain step with the solved frame acceleration", "[unit][beam]") {
  Bent b;
  const double dt = 0.01, s = 0.37;
  FrameAccelerationDirection dir;
  dir.acceleration_m_s2 = Vec3(0.0, 0.4, 0.1);
  dir.angular_acceleration_rad_s2 = Vec3(0.0, 0.0, 1.0);
  DynamicOptions options;
  options.matrix_max_age = 1;  // a fresh step matrix every step, so both paths solve with one A
  BeamState plain = b.state, halves = b.state;
  DynamicStepper stepper_plain(b.model, options), stepper_halves(b.model, options);
  for (int k = 0; k < 5; ++k) {
    const BeamInput in = input_at(4.0 + (k + 1) * dt);
    BeamInput solved = in;
    solved.frame.acceleration_m_s2 += s * dir.acceleration_m_s2;
    solved.frame.angular_acceleration_rad_s2 += s * dir.angular_acceleration_rad_s2;
    const Vec6 root_before = root_reaction(b.model, halves);
    stepper_plain.step(solved, dt, plain);
    const AffineRootLoad root = stepper_halves.prepare(in, dir, dt, halves);
    stepper_halves.finish(s, halves);
    // The residual is exact in both; the step matrix A is built at s = 0 in one and at s in the
    // other (the frame acceleration enters A's inertial stiffness), which only steers the
    // correction (solvers.hpp, matrix reuse): measured ≤ 2e-7 of a unit quantity, bound 1e-5.
    CHECK(max_abs_diff(plain, halves) <= 1e-5);
    // The affine root load is the balance-time (ρ∞ = 0: end-of-step) load of the linearised
    // step; the nonlinear root reaction after the exact base update differs by the terms the
    // piecewise-linear scheme drops, e.g. N θ²/2 of the root section's axial force N turned by
    // the step's rotation θ. Measured 1.1e-4 of the load (0.12 N of 1150 N; the step changes
    // the load by 0.69 N), bound 1e-3.
    const Vec6 predicted = root.at_zero + s * root.per_unit;
    const Vec6 actual = root_reaction(b.model, halves);
    // And it beats holding the last root load (what an explicit exchange hands on): measured
    // error / change of the load over the step 0.18; bound 0.5.
    CHECK((predicted - actual).norm() < 0.5 * (root_before - actual).norm());
  }
}

TEST_CASE("a beam step that fails its small-angle check leaves the state as it was", "[unit][beam]") {
  Bent b;
  DynamicOptions options;
  options.max_increment_rad = 1e-9;
  DynamicStepper stepper(b.model, options);
  BeamState state = b.state;
  CHECK_THROWS_AS(stepper.step(input_at(4.01), 0.01, state), NumericalError);
  CHECK(max_abs_diff(state, b.state) == 0.0);
  CHECK(state.time_s == b.state.time_s);
  CHECK(state.step_matrix.age == b.state.step_matrix.age);
  // And a retry with a normal limit goes on from it.
  DynamicStepper retry(b.model, DynamicOptions{});
  CHECK_NOTHROW(retry.step(input_at(4.01), 0.01, state));
}

TEST_CASE("a copied beam state continues bit-identically, factor cache included", "[unit][beam]") {
  Bent b;
  DynamicStepper first(b.model, DynamicOptions{});
  BeamState original = b.state;
  for (int k = 0; k < 7; ++k) first.step(input_at(4.0 + (k + 1) * 0.01), 0.01, original);
  BeamState copy = original;  // mid-way through the cached matrix's life
  DynamicStepper second(b.model, DynamicOptions{});
  for (int k = 7; k < 40; ++k) {
    first.step(input_at(4.0 + (k + 1) * 0.01), 0.01, original);
    second.step(input_at(4.0 + (k + 1) * 0.01), 0.01, copy);
  }
  CHECK(max_abs_diff(original, copy) == 0.0);
}

TEST_CASE("a span gauge at the root is the root load, and strain energy is zero undeformed", "[unit][beam]") {
  Bent b;
  const Vec6 root = root_reaction(b.model, b.state);
  // The root section: loads on the root, moment about the point α of the way to node 0, moved
  // back to the root point — the same six numbers to rounding.
  Vec6 gauge = section_load_at(b.model, b.state, 0.0);
  const Vec3 arm = b.model.sections.front().alpha * (b.state.position_m[0] - b.model.root_position_m);
  gauge.tail<3>() += arm.cross(Vec3(gauge.head<3>()));
  CHECK((gauge - root).norm() <= 1e-9 * root.norm());
  CHECK(strain_energy(b.model, make_state(b.model)) == 0.0);
}

TEST_CASE("a span gauge in its section's frame is the section's stress resultant C [γ; κ]", "[unit][beam]") {
  // What a strain gauge measures: without strain rates (velocities zeroed, so no damping part) the
  // internal load turned into the section's own frame is the elastic resultant of its strains, at
  // every section of the deflected Kane beam. Rounding only: one rotation of the same numbers.
  Bent b;
  for (Vec6& v : b.state.velocity) v.setZero();
  for (const double eta : {0.0, 0.3, 0.77}) {
    INFO("eta " << eta);
    const Mat3 frame = section_frame_at(b.model, b.state, eta);
    const Vec6 load = section_load_at(b.model, b.state, eta);
    Vec6 local;
    local << frame.transpose() * load.head<3>(), frame.transpose() * load.tail<3>();
    // The section's own resultant, from its strains (the nearest section to eta, as the gauge takes).
    const SectionModel* nearest = &b.model.sections.front();
    for (const SectionModel& sec : b.model.sections) {
      const double s_mid = (sec.inboard >= 0 ? b.model.nodes[sec.inboard].s_m : 0.0) + sec.alpha * sec.length_m;
      const double s_best = (nearest->inboard >= 0 ? b.model.nodes[nearest->inboard].s_m : 0.0) + nearest->alpha * nearest->length_m;
      if (std::abs(s_mid - eta * b.model.length_m) < std::abs(s_best - eta * b.model.length_m)) nearest = &sec;
    }
    NodePose pa, pb;
    section_poses(b.model, b.state, *nearest, pa, pb);
    SectionLinearization lin;
    linearize_section(*nearest, pa, pb, lin);
    CHECK((frame - lin.orientation).norm() == 0.0);
    // The outboard part pulls on the inboard: +S, force and moment about the section point.
    CHECK((local - lin.resultant).norm() <= 1e-10 * lin.resultant.norm());
  }
  // A frame, orthonormal, and turned from the root's by the deflection: not the root frame outboard.
  const Mat3 tip_frame = section_frame_at(b.model, b.state, 0.9);
  CHECK((tip_frame.transpose() * tip_frame - Mat3::Identity()).norm() < 1e-14);
  CHECK((tip_frame - b.model.root_orientation).norm() > 1e-3);
  CHECK(strain_energy(b.model, b.state) > 0.0);
}
