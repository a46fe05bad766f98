// A riser hung from the floating turbine (scenes/turbine_riser.hpp, issue 26): its static hang-off
// tension against the closed form of a vertical tensioned line, a held platform in still water
// moving nothing, its top load entering the platform's equations, the step allocating nothing, and
// a bad deck stopping at its line. The restart is in restart_tests.cpp.
#include <atomic>
#include <cmath>
#include <fstream>
#include <numbers>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/deck.hpp"
#include "fowtsim/testing/skip.hpp"
#include "scenes/floating_scene.hpp"

// The counters of fowtsim/testing/allocation_counter.hpp, whose replacement operator new this
// executable takes from flexible_rotor_tests.cpp (the header may be included in one file only).
namespace fowtsim::testing {
inline std::atomic<bool> counting{false};
inline std::atomic<long> allocations{0};
}  // namespace fowtsim::testing

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

// The seed's riser tube (seed 000 §3.5.3), empty: a cable-like line without contents.
constexpr double kOuter = 0.254, kInner = 0.2286, kYoungs = 209e9, kSteel = 7800.0, kWater = 1025.0, kG = 9.80665;

std::string riser_keys(const std::string& anchor, double stretch_m) {
  return "riser:\n  anchor_m: " + anchor + "\n  hang_off_m: [0.0, 0.0, -120.0]\n  stretch_m: " + std::to_string(stretch_m) +
         "\n  outer_diameter_m: 0.254\n  inner_diameter_m: 0.2286\n  youngs_modulus_Pa: 209.0e9\n  density_kg_m3: 7800.0\n"
         "  damping_mu_s: 0.001\n  inertia_coefficient: 1.8\n  drag_coefficient: 1.0\n  segments: 40\n"
         "  moment_gauges_eta: [0.5]\n";
}

// OC3-Hywind's structure and Morison hydro with the platform DOFs of `free` free (the others held),
// the rotor held at rest, and the riser.
io::ValidatedDeck riser_deck(const std::string& name, const std::string& free, const std::string& extra) {
  const auto dir = testing::scratch_dir("riser_turbine_" + name);
  const auto oc3 = testing::source_dir() / "inputs/oc3_hywind";
  std::ofstream(dir / "deck.yaml") << "include: [" << (oc3 / "structure.yaml").string() << ", " << (oc3 / "hydro.yaml").string()
                                   << "]\nsimulation: {t_max_s: 10.0, dt_s: 0.0125}\n"
                                   << "structure:\n  degrees_of_freedom: {surge: " << (free == "surge" ? "true" : "false")
                                   << ", sway: false, heave: false, roll: false, pitch: false, yaw: false, rotor_speed: held}\n"
                                   << extra;
  return io::read_deck(floating_scene_schema(), dir / "deck.yaml");
}

double area(double d) { return 0.25 * std::numbers::pi * d * d; }

}  // namespace

TEST_CASE("a vertical riser hangs at the closed-form tension of a tensioned line", "[verification][riser]") {
  const double stretch = 0.05;
  const io::ValidatedDeck deck = riser_deck("static", "none", riser_keys("[0.0, 0.0, -320.0]", stretch));
  FloatingScene scene(deck);
  const FloatingState s = scene.make_state();
  const TurbineRiser& riser = *scene.riser();
  const Vec3 top = riser.top_load(s.riser->line).head<3>();     // on the platform
  const Vec3 bottom = riser.bottom_load(s.riser->line).head<3>();  // on the anchor
  // A vertical line of unstretched length L, submerged weight w per length, its top raised by δ:
  // T(s) = T_bottom + w s, and δ = ∫ T/EA ds gives T_top = EA δ/L + w L/2, T_bottom = EA δ/L − w L/2.
  const double length = 200.0 - stretch;
  const double w = (kSteel * (area(kOuter) - area(kInner)) - kWater * area(kOuter)) * kG;
  const double ea = kYoungs * (area(kOuter) - area(kInner));
  const double top_closed = ea * stretch / length + 0.5 * w * length;
  const double bottom_closed = ea * stretch / length - 0.5 * w * length;
  INFO("top " << -top.z() << " N (closed form " << top_closed << "), bottom " << bottom.z() << " N (" << bottom_closed << ")");
  // Equilibrium of the line: the two ends carry its submerged weight. Measured 1.7e-10 relative:
  // bound 1e-9 (the static solver stops at increments of 1e-10 of the length).
  CHECK(std::abs(-top.z() - bottom.z() - w * length) < 1e-9 * w * length);
  // The closed form: the tension is linear along the line, which the volumes' piecewise-constant
  // strain integrates exactly, and the beam's axial strain is the stretch, linear in EA; measured
  // 2.8e-12 (top) and 1.9e-11 (bottom) relative; bound 2e-10 (the static solver's 1e-10 tolerance).
  CHECK(std::abs(-top.z() / top_closed - 1.0) < 2e-10);
  CHECK(std::abs(bottom.z() / bottom_closed - 1.0) < 2e-10);
  // The line hangs straight down: nothing horizontal (measured exactly 0).
  CHECK(top.head<2>().norm() < 1e-9 * top.norm());
}

TEST_CASE("with the platform held in a still sea nothing moves on the riser", "[verification][riser]") {
  const io::ValidatedDeck deck = riser_deck("still", "none", riser_keys("[0.0, 0.0, -320.0]", 0.05));
  FloatingScene scene(deck);
  FloatingState s = scene.make_state();
  const double dt = 0.0125;
  const Vec6 top0 = scene.riser()->top_load(s.riser->line);
  for (int k = 0; k < 400; ++k) scene.step(k * dt, dt, s);  // 5 s
  double speed = 0.0;
  for (const Vec6& v : s.riser->line.velocity) speed = std::max(speed, v.norm());
  const Vec6 top = scene.riser()->top_load(s.riser->line);
  INFO("largest node speed " << speed << " m/s, top load change " << (top - top0).norm() << " N");
  // The static solution is an equilibrium of the dynamic step (the same residual): measured node
  // speeds of 1.6e-12 m/s and a top-load change of 1.0e-7 N (2e-13 of the 526 kN top load), the
  // rounding of the residual at a 526 kN tension; bounds 2e-11 m/s and 2e-12 of the load.
  CHECK(speed < 2e-11);
  CHECK((top - top0).norm() < 2e-12 * top0.norm());
}

TEST_CASE("the riser's top load moves the platform to the balance of its spring", "[verification][riser]") {
  // Intent: the top load enters the platform's equations with its sign and size. An inclined
  // riser (anchor 30 m downstream) pulls the platform along x; surge is the only free DOF, on a
  // linear spring K (AddCLin) critically damped (AddBLin): the platform settles where K x equals
  // the line's horizontal pull at that position.
  const double k_surge = 4e6;  // [N/m]
  const std::string hydro = "hydro:\n  added_stiffness: [4.0e6, 0, 0, 0, 0, 0,  0, 0, 0, 0, 0, 0,  0, 0, 0, 0, 0, 0,  0, 0, 0, 0, 0, 0,"
                            "  0, 0, 0, 0, 0, 0,  0, 0, 0, 0, 0, 0]\n"
                            "  added_damping: [1.6e7, 0, 0, 0, 0, 0,  0, 0, 0, 0, 0, 0,  0, 0, 0, 0, 0, 0,  0, 0, 0, 0, 0, 0,"
                            "  0, 0, 0, 0, 0, 0,  0, 0, 0, 0, 0, 0]\n";
  const io::ValidatedDeck deck = riser_deck("balance", "surge", hydro + riser_keys("[30.0, 0.0, -320.0]", 0.05));
  FloatingScene scene(deck);
  FloatingState s = scene.make_state();
  const double pull0 = scene.riser()->top_load(s.riser->line).x();
  const double dt = 0.0125;
  for (int k = 0; k < 4000; ++k) scene.step(k * dt, dt, s);  // 50 s: ~25 surge time constants
  const double x = s.body.position_m.x();
  const double pull = scene.riser()->top_load(s.riser->line).x();
  INFO("surge " << x << " m, pull at t = 0 " << pull0 << " N, at the end " << pull << " N, K x = " << k_surge * x << " N");
  CHECK(pull0 > 1e4);  // the line pulls toward its anchor (+x), tens of kN
  // Settled: measured |K x − pull| 8.7e-5 of the pull (72 kN) and a surge speed of 2.7e-7 m/s.
  // The surge's own decay e^{−ωt}(1 + ωt), ω = 0.5 rad/s, is 4e-10 by now: what remains is the
  // line's lateral vibration, excited by the platform's approach and damped by quadratic drag
  // (an amplitude falling as 1/t only) and μ_K; bound 1e-3.
  CHECK(std::abs(k_surge * x - pull) < 1e-3 * pull);
  CHECK(std::abs(s.body.velocity_m_s.x()) < 1e-6);
}

TEST_CASE("the shipped riser deck's staggered exchange converges with the large step", "[verification][riser]") {
  // Intent: the explicit exchange at the shipped deck's ΔT (12.5 ms) is well inside its stable
  // range (it runs to ΔT = 0.2 s, PIPE.md "On the floating turbine") and the platform converges:
  // 10 s of the shipped deck at ΔT = 12.5, 25 and 50 ms, one line step per large step.
  auto surge_at_10s = [](double dt, const std::string& name) {
    const auto dir = testing::scratch_dir("riser_turbine_dt_" + name);
    std::ofstream(dir / "deck.yaml") << "include: [" << (testing::source_dir() / "inputs/oc3_hywind/turbine_riser_15mps.yaml").string()
                                     << "]\nsimulation: {dt_s: " << dt << "}\n";
    const io::ValidatedDeck deck = io::read_deck(floating_scene_schema(), dir / "deck.yaml");
    FloatingScene scene(deck);
    FloatingState s = scene.make_state();
    const long steps = std::lround(10.0 / dt);
    for (long k = 0; k < steps; ++k) scene.step(k * dt, dt, s);
    return s.body.position_m.x();
  };
  const double fine = surge_at_10s(0.0125, "fine"), mid = surge_at_10s(0.025, "mid"), coarse = surge_at_10s(0.05, "coarse");
  INFO("surge at 10 s: " << fine << ", " << mid << ", " << coarse << " m");
  // Measured differences to the 12.5 ms run 1.8e-3 and 5.6e-3 m (of a 9.4 m excursion from the
  // 10 m start): bounds 2e-2 and 6e-2 m, and the error growing with ΔT (a consistent exchange).
  CHECK(std::abs(mid - fine) < 2e-2);
  CHECK(std::abs(coarse - fine) < 6e-2);
  CHECK(std::abs(coarse - fine) > std::abs(mid - fine));
}

TEST_CASE("a large step with the riser allocates nothing", "[unit][riser]") {
  const io::ValidatedDeck deck = riser_deck("allocation", "surge", riser_keys("[30.0, 0.0, -320.0]", 0.05));
  FloatingScene scene(deck);
  FloatingState s = scene.make_state();
  const double dt = 0.0125;
  std::vector<double> row(scene.written().size());
  scene.step(0.0, dt, s);  // first step: workspaces sized
  scene.row(dt, s, row);
  testing::allocations = 0;
  testing::counting = true;
  for (int k = 1; k <= 50; ++k) {
    scene.step(k * dt, dt, s);
    scene.row((k + 1) * dt, s, row);
  }
  testing::counting = false;
  CHECK(testing::allocations == 0);
}

TEST_CASE("a riser whose stretch is not shorter than its span stops at the key's line", "[unit][riser]") {
  try {
    const io::ValidatedDeck deck = riser_deck("bad_stretch", "none", riser_keys("[0.0, 0.0, -320.0]", 250.0));
    FloatingScene scene(deck);
    FAIL("no InputError");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains("deck.yaml:") && Catch::Contains("riser.stretch_m") &&
                             Catch::Contains("the anchor is 200 m from the hang-off point"));
  }
}
