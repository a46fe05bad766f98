// Point springs and masses along the body, a clamped top (a hanging body), and the inertia-relief
// moment's end conditions (issue 25): against closed forms.
#include "fowtsim/core/brent.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/slender/bending_moment.hpp"
#include "fowtsim/slender/frequency_domain.hpp"
#include "fowtsim/slender/modes.hpp"
#include "fowtsim/slender/wave_kinematics.hpp"
#include "test_bodies.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

using namespace fowtsim::slender;
using namespace fowtsim::slender::testing;
using std::numbers::pi;

namespace {

Environment weightless_in_air() {
  Environment env;
  env.gravity_m_s2 = 0.0;
  env.still_water_level_m = -1.0;  // below the bottom: every strip dry
  return env;
}

// β of the cantilever with a tip mass μ = M/(mL) (Blevins, Formulas for natural frequency and
// mode shape, table 8-8 case 4): 1 + cos β cosh β + μβ(cos β sinh β − sin β cosh β) = 0, first root.
double tip_mass_beta(double mu) {
  const auto f = [mu](double b) {
    return 1.0 + std::cos(b) * std::cosh(b) + mu * b * (std::cos(b) * std::sinh(b) - std::sin(b) * std::cosh(b));
  };
  return fowtsim::brent_root(f, 0.1, 1.9, f(0.1), f(1.9), 1e-15, 200);
}

// |M(0)| against the peak along the body, M(0) extrapolated linearly from the first two midpoints
// (x = Δx/2, 3Δx/2): second order in Δx.
double end_ratio(const VecXc& moment) { return std::abs(1.5 * moment(0) - 0.5 * moment(1)) / moment.cwiseAbs().maxCoeff(); }

}  // namespace

TEST_CASE("rigid bar on two point springs with a point mass at its centre: sway 2k/(mL + M), rotation", "[verification]") {
  const double L = 20.0, k = 3e5, M = 4000.0;
  BodyDescription body;
  body.strips = uniform_strips(40, L, steel_tube());
  body.shapes = floating_shapes(0, L, L / 2);
  body.point_springs = {{L / 4, k, 0.0}, {3 * L / 4, k, 0.0}};
  body.point_masses = {{L / 2, M, 0.0}};
  const Model model = make_model(body, weightless_in_air());
  const Modes modes = compute_modes(model);
  const double m = model.strips.mass_kg_m(0), dx = L / 40;
  // Springs at ±L/4 about the centre: k_θ = 2k(L/4)²; the point mass on the axis adds no rotary
  // inertia. The midpoint sum of the bar's inertia is L³/12 − LΔx²/12 (as in modes_tests.cpp):
  // both closed forms hold to rounding, 1e-13.
  CHECK(modes.omega_rad_s(0) == Approx(std::sqrt(2 * k / (m * L + M))).epsilon(1e-13));
  CHECK(modes.omega_rad_s(1) == Approx(std::sqrt(2 * k * L * L / 16 / (m * (L * L * L / 12 - L * dx * dx / 12)))).epsilon(1e-13));
}

TEST_CASE("cantilever with a tip point mass against the closed form and Rayleigh's estimate", "[verification]") {
  const double L = 50.0;
  for (const double mu : {0.5, 2.0}) {
    BodyDescription body;
    body.strips = uniform_strips(400, L, steel_tube());
    body.bottom_support = Support::Clamped;
    body.shapes = clamped_free_shapes(8, L);
    const double mL = make_model(body, weightless_in_air()).strips.mass_kg_m(0) * L;
    body.point_masses = {{L, mu * mL, 0.0}};
    const Model model = make_model(body, weightless_in_air());
    const double EI = model.strips.bending_stiffness_N_m2(0), m = model.strips.mass_kg_m(0);
    const double beta = tip_mass_beta(mu);
    const double exact = beta * beta / (L * L) * std::sqrt(EI / m);
    const double rayleigh = std::sqrt(3 * EI / (L * L * L * (mu * mL + 33.0 / 140.0 * mL)));  // static tip-load shape
    const double omega = compute_modes(model, 1).omega_rad_s(0);
    INFO("μ = " << mu << ": Ritz " << omega << ", closed form " << exact << " (β " << beta << "), Rayleigh " << rayleigh);
    // Ritz with 8 cantilever modes (which do not carry the tip mass's shear condition) on 400
    // strips: measured 1.9e-5 (μ 0.5) and 3.2e-5 (μ 2); 3e-4 (10×). Ritz bounds it from above.
    CHECK(omega == Approx(exact).epsilon(3e-4));
    CHECK(omega >= exact * (1 - 1e-12));
    // Rayleigh's quotient with the static tip-load shape (effective mass 33/140 mL) is an upper
    // bound too: measured 0.15 % (μ 0.5) and 0.016 % (μ 2) above; 1 % (7×).
    CHECK(rayleigh >= exact);
    CHECK(rayleigh == Approx(exact).epsilon(1e-2));
  }
}

TEST_CASE("clamped top, free bottom: the hanging cantilever's modes are the cantilever's", "[verification]") {
  const double L = 50.0;
  BodyDescription body;
  body.strips = uniform_strips(200, L, steel_tube());
  body.top_support = Support::Clamped;
  body.shapes = free_clamped_shapes(6, L);
  const Model model = make_model(body, weightless_in_air());
  const Modes modes = compute_modes(model, 3);
  const double EI = model.strips.bending_stiffness_N_m2(0), m = model.strips.mass_kg_m(0);
  for (int n = 1; n <= 3; ++n) {
    const double beta = clamped_free_beta(n);
    // The mirror image of modes_tests.cpp's clamped–free body: the same 1.65e-8 at 200 strips, 2e-7 (10×).
    CHECK(modes.omega_rad_s(n - 1) == Approx(beta * beta / (L * L) * std::sqrt(EI / m)).epsilon(2e-7));
  }
  // A clamped top needs a free bottom: with both ends held the inertia relief has no statics.
  body.bottom_support = Support::Pinned;
  CHECK_THROWS_AS(make_model(body, weightless_in_air()), fowtsim::InputError);
}

namespace {

// A 50-m tube standing in 60 m of water in a regular wave (T 5 s, a 1.5 m), drag on: the harmonic
// FD response and its two moments.
struct Moments {
  VecXc elastic, relief;
};
Moments harmonic_moments(BodyDescription body, int strips = 400, double g = 9.80665) {
  body.strips = uniform_strips(strips, 50.0, steel_tube());
  Environment env;
  env.gravity_m_s2 = g;
  env.still_water_level_m = 60.0;
  env.water_depth_m = 60.0;
  const Model model = make_model(body, env);
  const Modes modes = compute_modes(model, 4);
  const double omega = 2 * pi / 5.0;
  const HarmonicResponse r = solve_harmonic(model, modes, omega, 1.5, velocity_transfer(model, omega));
  return {elastic_moment<std::complex<double>>(model, r.q),
          inertia_relief_moment<std::complex<double>>(model, harmonic_load_per_length(model, r), r.q, harmonic_inertial_q(model, r))};
}

double difference(const Moments& m) { return (m.relief - m.elastic).cwiseAbs().maxCoeff() / m.relief.cwiseAbs().maxCoeff(); }

}  // namespace

// max |IR − EI v''| / max |IR| for 8, 16, 32 shapes on 50 strips per shape.
std::vector<double> refinement(BodyDescription body, std::vector<ShapeFunction> (*family)(int, double)) {
  std::vector<double> d;
  for (const int shapes : {8, 16, 32}) {
    body.shapes = family(shapes, 50.0);
    d.push_back(difference(harmonic_moments(body, 50 * shapes)));
  }
  return d;
}

TEST_CASE("inertia relief with a clamped top sums from the free bottom and converges to EI v''", "[verification]") {
  BodyDescription body;
  body.top_support = Support::Clamped;
  const std::vector<double> d = refinement(body, free_clamped_shapes);
  INFO("max |IR − EI v''| / max |IR| at 8, 16, 32 shapes: " << d[0] << ", " << d[1] << ", " << d[2]);
  // Measured 9.3e-2, 2.7e-2, 7.1e-3: the hanging body's tension (the weight below) makes the
  // cantilever shapes converge at second order (×3.5, ×3.7 per doubling); a wrong sign of any
  // term of the bottom sum stalls it. Falls ≥ 3× per doubling; 1.5e-2 at 32 shapes (2×: a
  // convergence check, the value is not noise).
  CHECK(d[1] < d[0] / 3.0);
  CHECK(d[2] < d[1] / 3.0);
  CHECK(d[2] < 1.5e-2);
}

TEST_CASE("inertia relief counts a point mass's d'Alembert force and a point spring's force", "[verification]") {
  BodyDescription body;
  body.bottom_support = Support::Clamped;
  body.point_masses = {{40.0, 2e4, 0.0}};
  body.point_springs = {{30.0, 2e5, 0.0}};
  const std::vector<double> d = refinement(body, clamped_free_shapes);
  INFO("max |IR − EI v''| / max |IR| at 8, 16, 32 shapes: " << d[0] << ", " << d[1] << ", " << d[2]);
  // Measured 6.0e-2, 3.6e-2, 1.8e-2: EI v'' of smooth shapes converges at first order to the
  // shear jumps at the points (×1.7, ×2.0 per doubling), the inertia relief has them exactly;
  // without the point forces in the balance the difference would stay at their share of the
  // base moment. Falls ≥ 1.5× per doubling; 3e-2 at 32 shapes (a convergence check).
  CHECK(d[1] < d[0] / 1.5);
  CHECK(d[2] < d[1] / 1.5);
  CHECK(d[2] < 3e-2);
}

TEST_CASE("inertia relief's end conditions: M → 0 at a free-floating body's free bottom, M(0) = 0 under a pinned top", "[verification]") {
  SECTION("free-floating rigid body: the top sum closes at the free bottom") {
    // Rigid shapes only: their Galerkin equations are the body's force and moment balance (with
    // the end springs' forces), so the sum from the top closes at the free bottom.
    for (const int strips : {100, 400}) {
      BodyDescription body;
      body.strips = uniform_strips(strips, 50.0, steel_tube());
      body.shapes = floating_shapes(0, 50.0, 25.0);
      body.top_springs.translational_N_m = body.bottom_springs.translational_N_m = 1e5;
      Environment env;
      env.still_water_level_m = 40.0;
      env.water_depth_m = 200.0;
      const Model model = make_model(body, env);
      const Modes modes = compute_modes(model);
      const double omega = 2 * pi / 8.0;
      const HarmonicResponse r = solve_harmonic(model, modes, omega, 1.0, velocity_transfer(model, omega));
      const VecXc relief =
          inertia_relief_moment<std::complex<double>>(model, harmonic_load_per_length(model, r), r.q, harmonic_inertial_q(model, r));
      INFO(strips << " strips: |M(0)| / max |M| = " << end_ratio(relief));
      // Measured 7.3e-5 (100 strips) and 4.5e-6 (400): the extrapolation's O(Δx²). 7e-4, 5e-5 (10×).
      CHECK(end_ratio(relief) < (strips == 100 ? 7e-4 : 5e-5));
    }
  }
  SECTION("pinned-top tensioned riser: the top reaction closes M(0) = 0") {
    for (const int strips : {100, 400}) {
      BodyDescription body;
      body.strips = uniform_strips(strips, 300.0, {0.0, 0.254, 0.2286, 7800.0, 2.09e11, 1.0, 0.8, 0.0});
      body.bottom_support = body.top_support = Support::Pinned;
      body.top_tension_N = 2e6;
      body.shapes = pinned_pinned_shapes(16, 300.0);
      Environment env;
      env.still_water_level_m = 300.0;
      env.water_depth_m = 300.0;
      const Model model = make_model(body, env);
      const Modes modes = compute_modes(model, 8);
      const double omega = 2 * pi / 10.0;
      const HarmonicResponse r = solve_harmonic(model, modes, omega, 3.0, velocity_transfer(model, omega));
      const VecXc relief =
          inertia_relief_moment<std::complex<double>>(model, harmonic_load_per_length(model, r), r.q, harmonic_inertial_q(model, r));
      INFO(strips << " strips: |M(0)| / max |M| = " << end_ratio(relief));
      // Measured 1.6e-3 (100 strips) and 2.7e-5 (400): the top reaction R that closes the sum at
      // x = 0 holds it there to the extrapolation's order. 1.5e-2, 3e-4 (10×).
      CHECK(end_ratio(relief) < (strips == 100 ? 1.5e-2 : 3e-4));
    }
  }
}
