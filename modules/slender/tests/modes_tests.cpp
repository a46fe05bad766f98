// Undamped modes against closed forms (seed 004, slide "Undamped Modes"), and the assembly of
// T_eff (slide "Development Strategy"). Closed forms assume no self-weight: those tests set g = 0,
// so T_eff is the top tension alone.
#include "fowtsim/core/error.hpp"
#include "fowtsim/slender/modes.hpp"
#include "test_bodies.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

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

}  // namespace

TEST_CASE("clamped_free_beta gives the cantilever's tabulated roots", "[unit]") {
  // Blevins, Formulas for natural frequency and mode shape, Table 8-1: 1.87510407, 4.69409113, 7.85475744.
  CHECK(clamped_free_beta(1) == Approx(1.87510407).epsilon(1e-8));  // table's 9 digits
  CHECK(clamped_free_beta(2) == Approx(4.69409113).epsilon(1e-8));
  CHECK(clamped_free_beta(3) == Approx(7.85475744).epsilon(1e-8));
}

TEST_CASE("uniform clamped-free beam: ω_n = (β_n/L)² √(EI/m) to the strips' midpoint-rule error", "[verification]") {
  const double L = 60.0;
  const double beta[] = {1.8751040687, 4.6940911330, 7.8547574382};
  BodyDescription body;
  body.bottom_support = Support::Clamped;
  body.shapes = clamped_free_shapes(6, L);
  double previous_error = 1.0;
  for (int strips : {50, 100, 200}) {
    body.strips = uniform_strips(strips, L, steel_tube());
    const Model model = make_model(body, weightless_in_air());
    const Modes modes = compute_modes(model);
    const double EI = model.strips.bending_stiffness_N_m2(0), m = model.strips.mass_kg_m(0);
    double worst = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double exact = std::pow(beta[k] / L, 2) * std::sqrt(EI / m);
      worst = std::max(worst, std::abs(modes.omega_rad_s(k) / exact - 1.0));
    }
    // Measured worst relative error (mode 3): 4.3e-6, 2.6e-7, 1.65e-8 for 50, 100, 200 strips:
    // the midpoint rule on exact eigenfunctions, fourth order: the Rayleigh quotient is stationary
    // at an eigenfunction, and the O(Δx²) rule errors of K and M cancel to leading order.
    INFO("strips " << strips << " worst relative error " << worst);
    if (strips == 200) CHECK(worst < 2e-7);  // 10× the measured 1.65e-8
    CHECK(worst < previous_error / 10.0);  // measured ratio 16 per halving of Δx (fourth order)
    previous_error = worst;
  }
}

TEST_CASE("tensioned pinned-pinned beam: ω_n = (nπ/L)²√(EI/m)√(1 + TL²/(EI n²π²))", "[verification]") {
  const double L = 300.0, T = 2.0e6;
  BodyDescription body;
  body.bottom_support = body.top_support = Support::Pinned;
  body.top_tension_N = T;
  body.strips = uniform_strips(150, L, steel_tube());
  body.shapes = pinned_pinned_shapes(10, L);
  const Model model = make_model(body, weightless_in_air());
  const Modes modes = compute_modes(model);
  const double EI = model.strips.bending_stiffness_N_m2(0), m = model.strips.mass_kg_m(0);
  for (int n = 1; n <= 5; ++n) {
    const double exact = std::pow(n * pi / L, 2) * std::sqrt(EI / m) * std::sqrt(1.0 + T * L * L / (EI * n * n * pi * pi));
    // Sines sampled at strip midpoints are discretely orthogonal (Σ sin sin = N/2 δ), so the
    // midpoint rule is exact here: measured < 1e-14; tolerance rounding, 1e-12.
    CHECK(modes.omega_rad_s(n - 1) == Approx(exact).epsilon(1e-12));
  }
  // Untensioned, the same beam: ω_n = (nπ/L)² √(EI/m).
  body.top_tension_N = 0.0;
  const Modes bare = compute_modes(make_model(body, weightless_in_air()));
  for (int n = 1; n <= 3; ++n)
    CHECK(bare.omega_rad_s(n - 1) == Approx(std::pow(n * pi / L, 2) * std::sqrt(EI / m)).epsilon(1e-12));
}

TEST_CASE("frequencies fall monotonically as shapes are added (Rayleigh–Ritz), a riser under self-weight", "[verification]") {
  // A 300 m top-tensioned riser whose T_eff falls linearly with depth: no closed form, and the
  // sines are not its modes. Nested shape sets give upper bounds that fall monotonically. (A step
  // in EI, by contrast, puts a jump in v'' that a sine series resolves only as 1/n: measured 1.2e-4
  // then 8e-5 for 12 → 24 → 48 sines. Steps need more shapes, or strips and shapes refined together.)
  const double L = 300.0;
  BodyDescription body;
  body.bottom_support = body.top_support = Support::Pinned;
  body.top_tension_N = 1.5e6;
  body.strips = uniform_strips(300, L, steel_tube());
  Environment env;
  env.still_water_level_m = L - 10.0;
  Eigen::VectorXd previous = Eigen::VectorXd::Constant(3, 1e9);
  double change_last = 0.0;
  for (int n : {3, 6, 12, 24, 48}) {
    body.shapes = pinned_pinned_shapes(n, L);
    const Modes modes = compute_modes(make_model(body, env), 3);
    for (int k = 0; k < 3; ++k) CHECK(modes.omega_rad_s(k) <= previous(k) * (1.0 + 1e-13));  // Ritz bound, rounding
    change_last = ((previous - modes.omega_rad_s).array() / modes.omega_rad_s.array()).abs().maxCoeff();
    previous = modes.omega_rad_s;
  }
  // Measured: the last doubling (24 → 48 sines) moves the first three frequencies by 9.9e-8;
  // tolerance 1e-6 (10×): converged.
  INFO("relative change 24 -> 48 shapes " << change_last);
  CHECK(change_last < 1e-6);
}

TEST_CASE("T_eff of a uniform wet riser: T_top − (w − b)(L − x)", "[unit]") {
  const double L = 100.0, T = 8e5;
  BodyDescription body;
  body.top_tension_N = T;
  body.strips = uniform_strips(10, L, steel_tube());
  body.shapes = floating_shapes(0, L, 0.0);
  Environment env;
  env.still_water_level_m = 2 * L;  // all wet
  const Model model = make_model(body, env);
  const Strip s = steel_tube();
  const double w = s.density_kg_m3 * pi / 4 * (0.5 * 0.5 - 0.45 * 0.45) * env.gravity_m_s2;
  const double b = env.water_density_kg_m3 * pi / 4 * 0.5 * 0.5 * env.gravity_m_s2;
  for (int i = 0; i < 10; ++i)
    CHECK(model.strips.effective_tension_N(i) == Approx(T - (w - b) * (L - model.strips.x_m(i))).epsilon(1e-13));
}

TEST_CASE("rigid floating bar on end springs: sway 2k/(mL), rotation about the centre 6k/(mL)", "[verification]") {
  const double L = 20.0, k = 3e5;
  BodyDescription body;
  body.strips = uniform_strips(40, L, steel_tube());
  body.shapes = floating_shapes(0, L, L / 2);
  body.bottom_springs.translational_N_m = body.top_springs.translational_N_m = k;
  const Model model = make_model(body, weightless_in_air());
  const Modes modes = compute_modes(model);
  const double m = model.strips.mass_kg_m(0);
  // The midpoint rule gives ΣΔx (x_i − L/2)² = L³/12 − LΔx²/12 (exact sum, not the integral): the
  // rotation's closed form uses that sum, so both agree to rounding, 1e-13.
  const double dx = L / 40;
  CHECK(modes.omega_rad_s(0) == Approx(std::sqrt(2 * k / (m * L))).epsilon(1e-13));
  CHECK(modes.omega_rad_s(1) ==
        Approx(std::sqrt(2 * k * L * L / 4 / (m * (L * L * L / 12 - L * dx * dx / 12)))).epsilon(1e-13));
}

TEST_CASE("shapes that break a support are refused", "[unit]") {
  BodyDescription body;
  body.bottom_support = Support::Clamped;
  body.strips = uniform_strips(10, 10.0, steel_tube());
  body.shapes = pinned_pinned_shapes(3, 10.0);  // slope ≠ 0 at x = 0
  CHECK_THROWS_AS(make_model(body, Environment{}), fowtsim::InputError);
}
