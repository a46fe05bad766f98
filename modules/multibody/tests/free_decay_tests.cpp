// Free decay on constant linear springs — the analytic stand-in for the OC3 free decay: the heave
// period of the OC3 structure on the hydrostatic heave stiffness C33 = 332,941 N/m (PUBLISHED.md,
// WAMIT Spar.hst) is 2π √(M/C33), and with an added mass A33 handed in through AppliedLoads it is
// 2π √((M + A33)/C33).
#include <cmath>
#include <numbers>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/multibody/multibody.hpp"
#include "fowtsim/multibody/oc3.hpp"
#include "test_support.hpp"

using namespace fowtsim;
using namespace fowtsim::multibody;
using fowtsim::multibody::testing::LambdaProvider;

namespace {

// Period from the upward zero crossings of z(t) (linear interpolation between samples).
double measured_heave_period(double added_mass_kg) {
  Params p = oc3_hywind_params();
  p.drivetrain.torsional_flexibility = false;
  p.initial_conditions.platform_position_m = Vec3(0.0, 0.0, 1.0);
  const Model model = make_model(p);
  const double k33 = 332941.0, k11 = 41180.0;
  LambdaProvider provider([&](double, const State& s, AppliedLoads& out) {
    out.gravity = false;  // the springs act about the equilibrium; gravity would only shift it
    out.platform_force_N = Vec3(-k11 * s.position_m.x(), -k11 * s.position_m.y(), -k33 * s.position_m.z());
    out.platform_added_mass(2, 2) = added_mass_kg;
  });
  State s = Multibody::make_state(model);
  const double dt = 0.02;
  std::vector<double> crossings;
  double z_prev = s.position_m.z();
  for (int n = 0; n < 15000 && crossings.size() < 6; ++n) {
    Multibody::advance(model, provider, n * dt, dt, s);
    const double z = s.position_m.z();
    if (z_prev < 0.0 && z >= 0.0) crossings.push_back((n + z_prev / (z_prev - z)) * dt);
    z_prev = z;
  }
  REQUIRE(crossings.size() >= 2);
  return (crossings.back() - crossings.front()) / (crossings.size() - 1);
}

}  // namespace

TEST_CASE("heave free-decay period on C33 equals 2 pi sqrt(M / C33)", "[verification][multibody][free_decay]") {
  // M: hand sum of the deck masses: platform 7,466,330 + tower 249,718.0 + nacelle 240,000 +
  // rotor 110,000 = 8,066,048 kg → T = 30.93 s (0.0323 Hz; OpenFAST free decay with the real
  // hydro: 0.03245 Hz, PUBLISHED.md).
  const double m = 7466330.0 + 249718.003 + 240000.0 + 110000.0;
  for (const double added : {0.0, 2.0e6}) {
    const double t_exact = 2.0 * std::numbers::pi * std::sqrt((m + added) / 332941.0);
    const double t = measured_heave_period(added);
    WARN("heave period (A33 " << added << "): " << t << " s vs " << t_exact << " s, rel " << std::abs(t / t_exact - 1));
    // Measured 1.0e-7 (zero-crossing interpolation, RK4 at ω dt = 0.004, the weak heave–pitch
    // inertial coupling through the 1 cm horizontal CM offset); tolerance 10× that.
    CHECK(t == Approx(t_exact).epsilon(1e-6));
  }
}
