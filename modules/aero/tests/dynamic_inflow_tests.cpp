// Øye's dynamic inflow (dynamic_inflow.hpp) and the rotor's unsteady states (aero.hpp): the filter
// against the closed form of the two-filter system, the steady limit against steady BEM, the NREL
// 5MW rotor with UA + DBEMT in steady wind, a pitch step, and the cost of the unsteady models.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <catch2/catch.hpp>

#include "fowtsim/aero/aero.hpp"
#include "fowtsim/aero/rigid_rotor.hpp"
#include "fowtsim/core/module.hpp"
#include "nrel5mw_deck.hpp"

using namespace fowtsim;
using namespace fowtsim::aero;

static_assert(Module<Aero>);

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;

// Closed form of the two filters for a unit step of W_qs at t = 0 from a steady 0:
// W_int = 1 − (1 − k) e^{−t/τ1} (the k τ1 dW_qs/dt impulse makes W_int jump to k),
// W = 1 − (1 − k) λ2/(λ2 − λ1) e^{−λ1 t} + ((1 − k) λ2/(λ2 − λ1) − 1) e^{−λ2 t}.
double step_response(double t, double tau1, double tau2) {
  const double l1 = 1.0 / tau1, l2 = 1.0 / tau2, g = (1.0 - kOyeK) * l2 / (l2 - l1);
  return 1.0 - g * std::exp(-l1 * t) + (g - 1.0) * std::exp(-l2 * t);
}

struct Rotor {
  Params params;
  RigidRotor geometry{Vec3(0.0, 0.0, 90.0), 0.0, 0.0, 0.0, 1.5};
  Aero::Input in;
  Aero::Output out;
  Aero::State state;
  double omega = 12.1 * kPi / 30.0;
  explicit Rotor(Params p) : params(std::move(p)), in(make_input(params)), out(make_output(params)),
                             state(Aero::make_state(params)) {}
  void place(double t, double pitch, double wind) {
    place_rigid_rotor(params, geometry, omega * t, omega, pitch, in);
    in.inflow_velocity_m_s.colwise() = Vec3(wind, 0.0, 0.0);
  }
};

// The NREL 5MW rotor twice, quasi-steady and with UA + DBEMT, both tilted 5° with 2.5° precone.
struct RotorPair {
  Rotor quasi_steady, unsteady;
  RotorPair() : quasi_steady(aero::testing::load_nrel5mw_deck()), unsteady(with_unsteady_models()) {
    quasi_steady.geometry = unsteady.geometry = RigidRotor{Vec3(0.0, 0.0, 90.0), 0.0, 5.0 * kDegree, 2.5 * kDegree, 1.5};
  }
  static Params with_unsteady_models() {
    Params p = aero::testing::load_nrel5mw_deck();
    p.unsteady_airfoil = UnsteadyAirfoilModel::hgm;
    p.dynamic_inflow = DynamicInflowModel::oye;
    return p;
  }
};

}  // namespace

// Intent: the discrete update is the exact solution of the continuous filters, whatever the step.
TEST_CASE("Oye filter step response equals the closed form at any step size", "[unit][aero]") {
  const double tau1 = 8.0, tau2 = oye_tau2(tau1, 0.7);
  for (double dt : {0.01, 0.5, 5.0}) {
    OyeFilter f = oye_steady(0.0);
    double worst = 0.0;
    for (int i = 1; i * dt <= 60.0 + 1e-12; ++i) {
      // W_qs = 1 from t = 0+: z is continuous across the jump, so the hold is from 1 to 1.
      advance_oye(f, tau1, tau2, 1.0, 1.0, dt);
      worst = std::max(worst, std::abs(f.w - step_response(i * dt, tau1, tau2)));
    }
    // Exact up to round-off accumulated over ≤ 6000 steps: measured ≤ 3e-15; 1e-12.
    CHECK(worst < 1e-12);
  }
  // The steady filter is a fixed point bit for bit (the rotor's steady limit relies on it).
  OyeFilter f = oye_steady(3.7);
  advance_oye(f, tau1, tau2, 3.7, 3.7, 0.1);
  CHECK(f.w == 3.7);
  CHECK(f.z == oye_steady(3.7).z);
}

// Intent: with the states started in steady flow, UA + DBEMT give steady BEM exactly.
TEST_CASE("unsteady models started in steady flow reproduce steady BEM", "[unit][aero]") {
  RotorPair pair;
  Rotor& steady = pair.quasi_steady;
  Rotor& r = pair.unsteady;
  const Params& p = r.params;
  for (double wind : {5.0, 11.0, 18.0}) {
    const double pitch = wind > 11.4 ? 15.0 * kDegree : 0.0;
    steady.place(0.3, pitch, wind);
    evaluate(steady.params, steady.in, steady.state, steady.out);
    r.place(0.3, pitch, wind);
    r.state = Aero::make_state(p);
    evaluate(p, r.in, r.state, r.out);
    start_states(p, r.in, r.out, 0.3, r.state);
    evaluate(p, r.in, r.state, r.out);
    const double dp = std::abs(r.out.rotor.power_W / steady.out.rotor.power_W - 1.0);
    const double dt = std::abs(r.out.rotor.force_hub_N.x() / steady.out.rotor.force_hub_N.x() - 1.0);
    const double df = (r.out.force_N_m - steady.out.force_N_m).cwiseAbs().maxCoeff() / steady.out.force_N_m.cwiseAbs().maxCoeff();
    std::printf("steady limit %.0f m/s: dP %.1e, dT %.1e, node loads %.1e\n", wind, dp, dt, df);
    // a = (a_qs V_x)/V_x and α_E = α(1 − A1 − A2) + A1α + A2α round off only: measured ≤ 2e-15; 1e-12.
    CHECK(dp < 1e-12);
    CHECK(dt < 1e-12);
    CHECK(df < 1e-12);
  }
}

// Intent: the NREL 5MW rotor (tilt 5°, precone 2.5°: the blades see a once-per-revolution
// variation) in steady wind with UA + DBEMT settles to the quasi-steady power and thrust.
TEST_CASE("NREL 5MW rotor with UA and DBEMT in steady wind matches quasi-steady", "[verification][aero]") {
  RotorPair pair;
  Rotor& qs = pair.quasi_steady;
  Rotor& r = pair.unsteady;
  const Params& p = r.params;
  for (double wind : {8.0, 11.0, 16.0}) {
    const double pitch = wind > 11.4 ? 12.0 * kDegree : 0.0;
    const double dt = 0.02, period = 2.0 * kPi / r.omega;
    r.state = Aero::make_state(p);
    r.place(0.0, pitch, wind);
    evaluate(p, r.in, r.state, r.out);
    start_states(p, r.in, r.out, 0.0, r.state);
    double power = 0.0, thrust = 0.0, power_qs = 0.0, thrust_qs = 0.0;
    int samples = 0;
    const int steps = static_cast<int>(std::round(60.0 / dt));
    for (int i = 1; i <= steps; ++i) {
      const double t = i * dt;
      r.place(t, pitch, wind);
      evaluate(p, r.in, r.state, r.out);
      advance_states(p, r.in, r.out, dt, r.state);
      if (t > 60.0 - period) {  // the last revolution
        evaluate(p, r.in, r.state, r.out);
        qs.place(t, pitch, wind);
        evaluate(qs.params, qs.in, qs.state, qs.out);
        power += r.out.rotor.power_W, thrust += r.out.rotor.force_hub_N.x();
        power_qs += qs.out.rotor.power_W, thrust_qs += qs.out.rotor.force_hub_N.x();
        ++samples;
      }
    }
    const double dp = power / power_qs - 1.0, dth = thrust / thrust_qs - 1.0;
    std::printf("%.0f m/s settled (mean of the last revolution): power %+.4f %%, thrust %+.4f %%\n", wind, 100 * dp, 100 * dth);
    // The bound 0.5 %; measured below (see the printed figures / README).
    CHECK(std::abs(dp) < 0.005);
    CHECK(std::abs(dth) < 0.005);
  }
}

// Intent: a step in pitch: the filtered induction follows Øye's two time constants (closed form)
// and the thrust over/undershoots and relaxes (the Tjæreborg pitch-step behaviour).
TEST_CASE("DBEMT pitch step: induction relaxes with Oye's time constants", "[verification][aero]") {
  Params p = aero::testing::load_nrel5mw_deck();
  p.dynamic_inflow = DynamicInflowModel::oye;
  p.skew_model = SkewModel::none;  // axisymmetric rotor: W_qs constant at every node after the step
  Rotor r(p);
  const double wind = 11.4, dt = 0.01, t_step = 1.0;
  auto pitch = [&](double t) { return t < t_step - 1e-9 ? 0.0 : 4.0 * kDegree; };
  r.place(0.0, 0.0, wind);
  evaluate(p, r.in, r.state, r.out);
  start_states(p, r.in, r.out, 0.0, r.state);
  const double thrust_before = r.out.rotor.force_hub_N.x();
  const int node = 3 * 0 + 12;  // blade 1, node 13 (r ≈ 44.6 m, mid-outboard)
  const double w_before = r.state.nodes[node].axial.w;
  double w_after = 0.0, tau1 = 0.0, tau2 = 0.0, thrust_min = 1e30, worst = 0.0;
  std::vector<std::pair<double, double>> thrust_history;
  for (int i = 1; i * dt <= 40.0 + 1e-9; ++i) {
    const double t = i * dt;
    r.place(t, pitch(t), wind);
    evaluate(p, r.in, r.state, r.out);
    advance_states(p, r.in, r.out, dt, r.state);
    evaluate(p, r.in, r.state, r.out);
    if (t >= t_step) {
      if (tau1 == 0.0) {
        w_after = r.out.nodes[node].quasi_steady_axial_induced_m_s;
        tau1 = r.state.tau1_s;
        tau2 = oye_tau2(tau1, r.out.nodes[node].local_radius_m / r.out.rotor.radius_m);
      }
      // The hold makes the sampled step a ramp over [t_step − dt, t_step]: the closed form of a
      // step at its midpoint.
      const double expected = w_before + (w_after - w_before) * step_response(t - t_step + 0.5 * dt, tau1, tau2);
      worst = std::max(worst, std::abs(r.state.nodes[node].axial.w - expected) / std::abs(w_after - w_before));
      thrust_min = std::min(thrust_min, r.out.rotor.force_hub_N.x());
      thrust_history.emplace_back(t, r.out.rotor.force_hub_N.x());
    }
  }
  const double thrust_final = thrust_history.back().second;
  // Time for the thrust to recover 63 % from its minimum to its final value.
  double t63 = 0.0;
  for (const auto& [t, th] : thrust_history)
    if (t63 == 0.0 && th - thrust_min >= 0.632 * (thrust_final - thrust_min) && th > thrust_min + 1.0) t63 = t - t_step;
  std::printf("pitch step 0 -> 4 deg at 11.4 m/s: tau1 %.3f s, tau2(node 13) %.3f s, induced velocity %.4f -> %.4f m/s,"
              " worst |W - closed form| %.2e of the jump; thrust %.1f -> min %.1f -> %.1f kN, 63 %% recovery %.2f s\n",
              tau1, tau2, w_before, w_after, worst, thrust_before / 1e3, thrust_min / 1e3, thrust_final / 1e3, t63);
  // The ramp-vs-midpoint-step difference O((Δt/τ2)²) and τ1 at the transition step taken as the
  // mean of its values before and after (ā drops with the pitch): measured 1.1e-4; 1e-3.
  CHECK(worst < 1e-3);
  // Undershoot: right after feathering the held induction keeps α low, so the thrust drops below
  // its final value (measured 418.5 kN against a final 531.7 kN, −21 %) and relaxes: 2 % is far from both round-off and
  // the relaxation's remaining 1e-3 at 40 s.
  CHECK(thrust_min < thrust_final * 0.98);
  // The recovery follows Øye's two-filter response: the time the closed form of the mid-span node
  // needs to reach 63 % (k = 0.6 of the jump on τ2, the rest on τ1) against the thrust's: they
  // differ by 1 % (measured 4.23 s vs 4.19 s; the thrust integrates all nodes, τ2 falls with r,
  // and the loads are nonlinear in the induction); within ±10 %.
  double t_closed = 0.0;
  for (double t = 0.0; t < 60.0 && t_closed == 0.0; t += 0.001)
    if (step_response(t, tau1, tau2) >= 0.632) t_closed = t;
  std::printf("63 %% times: thrust %.2f s, node-13 closed form %.2f s (tau1 %.2f s)\n", t63, t_closed, tau1);
  CHECK(t63 > 0.9 * t_closed);
  CHECK(t63 < 1.1 * t_closed);
}

// Cost: one rotor evaluation (3 × 19 nodes) with UA + DBEMT against the quasi-steady one, and the
// state update per step. A benchmark print, not a timed assertion (shared machine).
TEST_CASE("cost of UA and DBEMT on a rotor evaluation", "[verification][aero]") {
  RotorPair pair;
  Rotor& qs = pair.quasi_steady;
  Rotor& r = pair.unsteady;
  const Params& p = r.params;
  r.place(0.0, 0.0, 11.0);
  evaluate(p, r.in, r.state, r.out);
  start_states(p, r.in, r.out, 0.0, r.state);
  const int repeats = 2000;
  auto time = [&](auto&& body) {
    double best = 1e30;
    for (int run = 0; run < 3; ++run) {
      const auto t0 = std::chrono::steady_clock::now();
      for (int i = 0; i < repeats; ++i) body(i);
      best = std::min(best, std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / repeats);
    }
    return best;
  };
  const double quasi = time([&](int i) {
    qs.place(0.01 * i, 0.0, 11.0);
    evaluate(qs.params, qs.in, qs.state, qs.out);
  });
  const double unsteady = time([&](int i) {
    r.place(0.01 * i, 0.0, 11.0);
    evaluate(p, r.in, r.state, r.out);
  });
  const double with_advance = time([&](int i) {
    r.place(0.01 * i, 0.0, 11.0);
    evaluate(p, r.in, r.state, r.out);
    advance_states(p, r.in, r.out, 0.01, r.state);
  });
  std::printf("evaluate(): quasi-steady %.1f us, UA + DBEMT %.1f us (x%.2f); evaluate + advance_states %.1f us (x%.2f)\n",
              quasi, unsteady, unsteady / quasi, with_advance, with_advance / quasi);
  CHECK(std::isfinite(unsteady));  // the figures are the output; the run must produce finite loads
  CHECK(r.out.rotor.power_W > 0.0);
}

// Intent: the module-contract advance() (allocating, for generic drivers) is evaluate() at the
// step's end + advance_states(), state for state.
TEST_CASE("Aero::advance equals evaluate plus advance_states", "[unit][aero]") {
  Params p = aero::testing::load_nrel5mw_deck();
  p.unsteady_airfoil = UnsteadyAirfoilModel::hgm;
  p.dynamic_inflow = DynamicInflowModel::oye;
  Rotor a(p), b(p);
  a.state = Aero::make_state(p);
  b.state = Aero::make_state(p);
  b.state.time_s = -0.05;  // advance() starts the states at t + dt, as advance_states() does from time_s
  CHECK_FALSE(Aero::make_state(aero::testing::load_nrel5mw_deck()).nodes.size() > 0);  // off: no states
  for (int i = 0; i <= 10; ++i) {
    const double t = 0.05 * i, wind = 10.0 + i;
    a.place(t, 0.0, wind);
    b.place(t, 0.0, wind);
    Aero::advance(p, a.in, t - 0.05, 0.05, a.state);
    evaluate(p, b.in, b.state, b.out);
    advance_states(p, b.in, b.out, 0.05, b.state);
  }
  REQUIRE(a.state.started);
  // The same operations, except that advance() solves the BEM cold on a fresh Output (no warm
  // start): roots agree to Brent's 1e-12 rad (measured: identical states); 1e-9.
  CHECK(std::abs(a.state.time_s - b.state.time_s) < 1e-12);
  double worst = 0.0;
  for (std::size_t k = 0; k < a.state.nodes.size(); ++k) {
    worst = std::max({worst, std::abs(a.state.nodes[k].axial.w - b.state.nodes[k].axial.w),
                      std::abs(a.state.nodes[k].airfoil.x4 - b.state.nodes[k].airfoil.x4),
                      std::abs(a.state.nodes[k].airfoil.x3 - b.state.nodes[k].airfoil.x3)});
  }
  std::printf("advance() vs evaluate + advance_states: worst state difference %.1e\n", worst);
  CHECK(worst < 1e-9);
}
