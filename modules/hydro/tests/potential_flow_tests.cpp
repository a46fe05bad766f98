// Potential flow inside the hydro module (params.hpp PotentialFlowParams, Hydrostatics::linear):
// what it adds to and removes from the Morison/hydrostatic model, on a synthetic radiation table.
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation.hpp"
#include "fowtsim/hydro/hydro.hpp"
#include "fowtsim/hydro/oc3.hpp"

using namespace fowtsim;
using namespace fowtsim::hydro;

namespace {

Params with_potential_flow(Params p, RadiationMethod method) {
  RadiationTable table;
  for (int k = 1; k <= 60; ++k) {
    const double w = 0.05 * k;
    table.frequencies_rad_s.push_back(w);
    table.damping.push_back(Mat6::Identity() * 2e5 * w * w * std::exp(-2.0 * w));
  }
  table.added_mass_infinite_frequency = Mat6::Identity() * 3e6;
  table.added_mass_infinite_frequency(0, 4) = table.added_mass_infinite_frequency(4, 0) = -1e7;
  RadiationOptions options;
  options.method = method;
  options.step_s = 0.02;
  options.window_s = 30.0;
  p.potential_flow = PotentialFlowParams{make_radiation_model(table, options), true};
  return p;
}

}  // namespace

TEST_CASE("with potential flow the members carry drag only, A(∞) is the added mass and the excitation passes through",
          "[unit][hydro]") {
  const Params morison = oc3_hywind_params();
  const Params potential = with_potential_flow(morison, RadiationMethod::convolution);
  Hydro::Input in = make_input(morison);
  in.fluid_acceleration_m_s2.row(0).setConstant(0.5);  // a uniform horizontal fluid acceleration, fluid at rest
  in.dynamic_pressure_Pa.setConstant(1000.0);
  in.wave_excitation << 1.0, 2.0, 3.0, 4.0, 5.0, 6.0;
  const Hydro::Output a = Hydro::outputs(morison, in, Hydro::make_state(morison, in));
  const Hydro::Output b = Hydro::outputs(potential, in, Hydro::make_state(potential, in));
  CHECK(std::abs(a.morison[0]) > 1e6);       // Froude–Krylov and diffraction inertia with Morison
  CHECK(b.morison.norm() == 0.0);            // no relative velocity: no drag, and nothing else
  CHECK(b.added_mass == potential.potential_flow->radiation.added_mass_infinite_frequency);
  CHECK(b.excitation == in.wave_excitation);
  CHECK(a.excitation.norm() == 0.0);         // ignored without potential flow
  CHECK(b.radiation.norm() == 0.0);          // at rest since ever
  // The total is the sum of the parts (no Morison, no radiation at rest): equal to rounding; 1e-9.
  CHECK((b.total - (b.buoyancy + b.added_linear + b.excitation)).norm() < 1e-9 * b.total.norm());
  // Drag stays: a surge velocity in still water meets ½ ρ C_d D |u| u over the wet length.
  in.fluid_acceleration_m_s2.setZero();
  in.dynamic_pressure_Pa.setZero();
  in.platform.velocity_m_s = Vec3(1.0, 0.0, 0.0);
  const Hydro::Output c = Hydro::outputs(potential, in, Hydro::make_state(potential, in));
  const double drag = 0.5 * 1025.0 * 0.6 * (9.4 * 108.0 + 0.5 * (9.4 + 6.5) * 8.0 + 6.5 * 4.0);
  CHECK(c.morison[0] == Approx(-drag).epsilon(1e-9));  // exact: the strips' midpoint rule integrates a linear taper exactly
}

TEST_CASE("linear hydrostatics: ρ g V0 at rest, − C_hst q when displaced", "[unit][hydro]") {
  Params p = with_potential_flow(oc3_hywind_params(), RadiationMethod::state_space);
  p.hydrostatics = Hydrostatics::linear;
  p.displaced_volume_m3 = 8029.21;
  p.hydrostatic_stiffness.setZero();
  p.hydrostatic_stiffness(2, 2) = 332941.0;
  p.hydrostatic_stiffness(4, 4) = -4.9992e9;
  validate(p);
  Hydro::Input in = make_input(p);
  const Hydro::State s = Hydro::make_state(p, in);
  // The same products as the closed form, evaluated in the same order: equal to rounding (1e-15);
  // the pitch moment passes through Euler angles of a rotation matrix (1e-12).
  const Hydro::Output rest = Hydro::outputs(p, in, s);
  CHECK(rest.buoyancy[2] == Approx(1025.0 * 9.80665 * 8029.21).epsilon(1e-15));
  CHECK(rest.buoyancy.norm() == Approx(rest.buoyancy[2]).epsilon(1e-15));
  in.platform.position_m.z() = -0.5;
  in.platform.orientation = euler123_to_matrix(Vec3(0.0, 0.1, 0.0));
  const Hydro::Output moved = Hydro::outputs(p, in, s);
  CHECK(moved.buoyancy[2] == Approx(1025.0 * 9.80665 * 8029.21 + 0.5 * 332941.0).epsilon(1e-15));
  CHECK(moved.buoyancy[4] == Approx(4.9992e9 * 0.1).epsilon(1e-12));
  p.displaced_volume_m3 = 0.0;
  CHECK_THROWS_AS(validate(p), InputError);
}

TEST_CASE("the convolution's stepped history sums equal the trapezoidal sum over the whole window", "[unit][hydro]") {
  // advance() derives the h = 0 part from the previous step's h = ΔT part; after more steps than
  // the window holds, the load at t_n must still be −[Σ_s w_s K(sΔT) q̇_{n−s}] summed afresh.
  const Params p = with_potential_flow(oc3_hywind_params(), RadiationMethod::convolution);
  const RadiationModel& m = p.potential_flow->radiation;
  const int n = m.window_steps;
  RadiationState s = make_radiation_state(m, 0.0, Vec6::Zero());
  std::vector<Vec6> velocities{Vec6::Zero()};
  for (int k = 1; k <= n + 40; ++k) {
    Vec6 v;
    for (int i = 0; i < 6; ++i) v[i] = std::sin(0.37 * k + i) + 0.3 * std::cos(1.9 * k * (i + 1));
    advance_radiation(m, k * m.step_s, v, s);
    velocities.push_back(v);
  }
  const std::size_t entries = m.entries.size();
  Vec6 direct = Vec6::Zero();
  for (int j = 0; j <= n; ++j) {
    const double w = (j == 0 || j == n) ? 0.5 * m.step_s : m.step_s;
    const Vec6& v = velocities[velocities.size() - 1 - static_cast<std::size_t>(j)];
    for (std::size_t e = 0; e < entries; ++e)
      direct[m.entries[e].row] -= w * m.kernel[static_cast<std::size_t>(2 * j) * entries + e] * v[m.entries[e].col];
  }
  const Vec6 load = radiation_load(m, s, s.time_s, velocities.back());
  CHECK((load - direct).norm() < 1e-12 * direct.norm());  // rounding: the sums differ in order only
}
