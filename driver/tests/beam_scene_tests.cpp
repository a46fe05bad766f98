// The YAML beam scene (our own beam deck format): the shipped roll-up deck closes its circle, bad
// beam decks stop before the run with file, line and key, and single-beam runs (beam decks and
// BeamDyn cases) go through the common time loop with BeamDyn's rows.
#include <cmath>
#include <fstream>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "beamdyn/beamdyn_channels.hpp"
#include "beamdyn/beamdyn_run.hpp"
#include "beamdyn/beamdyn_setup.hpp"
#include "decks/beam_deck.hpp"
#include "fowtsim/beam/beam_outputs.hpp"
#include "fowtsim/beam/pipe_benchmarks.hpp"
#include "fowtsim/beam/riser.hpp"
#include "fowtsim/beam/solvers.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/testing/skip.hpp"
#include "run/run_scene.hpp"
#include "run_request.hpp"
#include "scenes/beam_scene.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

TEST_CASE("the roll-up beam deck closes its circle", "[verification][beam_scene]") {
  const auto dir = testing::scratch_dir("beam_scene_rollup");
  run_scene(run_request(testing::source_dir() / "inputs/beams/rollup.yaml", dir / "rollup"), nullptr);
  const io::ChannelTable t = io::read_channels(dir / "rollup.out");
  // Exact: the tip returns to the root (TipTDz = −L, TipTDy = 0), turned by 2π (TipRD = 0); the
  // root moment equals the applied 4π. 100 second-order volumes: measured 1.2e-6 m.
  CHECK(std::abs(t.columns[*t.find("TipTDzr")].back() + 1.0) < 1e-5);
  CHECK(std::abs(t.columns[*t.find("TipTDyr")].back()) < 1e-5);
  CHECK(std::abs(t.columns[*t.find("TipRDxr")].back()) < 1e-5);
  // Exact balance, read back from a .out that keeps 10 significant digits.
  CHECK(std::abs(t.columns[*t.find("RootMxr")].back() - 4.0 * 3.14159265358979323846) < 1e-8);
}

TEST_CASE("bad beam decks stop before the run with file, line and key", "[unit][beam_scene]") {
  const auto dir = testing::scratch_dir("beam_scene_bad");
  const auto deck = dir / "beam.yaml";
  SECTION("a stiffness matrix with 35 entries") {
    std::ofstream(deck) << "simulation: {analysis: static}\nbeam:\n  key_points_m: [[0,0,0],[0,0,1]]\n  twist_deg: [0, 0]\n  stations:\n"
                           "    - {eta: 0, stiffness: [1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1], mass: [1,0,0,0,0,0, 0,1,0,0,0,0, 0,0,1,0,0,0, 0,0,0,1,0,0, 0,0,0,0,1,0, 0,0,0,0,0,1]}\n";
    CHECK_THROWS_WITH(run_scene(run_request(deck, dir / "run"), nullptr),
                      Catch::Contains("beam.yaml:6") && Catch::Contains("beam.stations[0].stiffness"));
    CHECK_FALSE(std::filesystem::exists(dir / "run.out"));
  }
  SECTION("one twist too few") {
    std::ofstream(deck) << "simulation: {analysis: static}\nbeam:\n  key_points_m: [[0,0,0],[0,0,0.5],[0,0,1]]\n  twist_deg: [0, 0]\n  stations:\n"
                           "    - {eta: 0, stiffness: [1,0,0,0,0,0, 0,1,0,0,0,0, 0,0,1,0,0,0, 0,0,0,1,0,0, 0,0,0,0,1,0, 0,0,0,0,0,1],"
                           " mass: [1,0,0,0,0,0, 0,1,0,0,0,0, 0,0,1,0,0,0, 0,0,0,1,0,0, 0,0,0,0,1,0, 0,0,0,0,0,1]}\n";
    CHECK_THROWS_WITH(run_scene(run_request(deck, dir / "run"), nullptr),
                      Catch::Contains("beam.yaml:4") && Catch::Contains("beam.twist_deg"));
  }
  SECTION("an unknown output channel") {
    std::ofstream(deck) << "simulation: {analysis: static}\noutput: {channels: [TipTDxr, OoPDefl1]}\n"
                           "beam:\n  key_points_m: [[0,0,0],[0,0,1]]\n  twist_deg: [0, 0]\n  stations:\n"
                           "    - {eta: 0, stiffness: [1,0,0,0,0,0, 0,1,0,0,0,0, 0,0,1,0,0,0, 0,0,0,1,0,0, 0,0,0,0,1,0, 0,0,0,0,0,1],"
                           " mass: [1,0,0,0,0,0, 0,1,0,0,0,0, 0,0,1,0,0,0, 0,0,0,1,0,0, 0,0,0,0,1,0, 0,0,0,0,0,1]}\n";
    CHECK_THROWS_WITH(run_scene(run_request(deck, dir / "run"), nullptr),
                      Catch::Contains("beam.yaml:2") && Catch::Contains("OoPDefl1"));
  }
}

TEST_CASE("OpenFAST channel names carry the same loads and deflections in their units",
          "[verification][beam_scene]") {
  // A quarter circle: tip moment (π/2)·EI/L on the roll-up beam turns the tip by exactly 90°
  // about x: TipRDxr = 4 tan(π/8) (Wiener–Milenkovic), TipRDxb1 = 90 deg, RootMxb1 = M/1000 kN·m.
  const auto dir = testing::scratch_dir("beam_scene_names");
  const auto deck = dir / "quarter.yaml";
  std::ofstream(deck) << "simulation: {analysis: static}\n"
                         "output: {channels: [TipRDxr, TipRDxb1, RootMxr, RootMxb1, B1RootMxr, TipTDyr, TipDyb1]}\n"
                         "beam:\n  segments: 100\n  key_points_m: [[0,0,0],[0,0,1]]\n  twist_deg: [0, 0]\n  stations:\n"
                         "    - {eta: 0, stiffness: [1e4,0,0,0,0,0, 0,1e4,0,0,0,0, 0,0,1e4,0,0,0, 0,0,0,2,0,0, 0,0,0,0,2,0, 0,0,0,0,0,2],"
                         " mass: [1,0,0,0,0,0, 0,1,0,0,0,0, 0,0,1,0,0,0, 0,0,0,0.1,0,0, 0,0,0,0,0.1,0, 0,0,0,0,0,0.2]}\n"
                         "loads: {tip_moment_N_m: [3.141592653589793, 0, 0]}\n";
  run_scene(run_request(deck, dir / "run"), nullptr);
  const io::ChannelTable t = io::read_channels(dir / "run.out");
  auto last = [&](const char* ch) { return t.columns[*t.find(ch)].back(); };
  const double pi = 3.14159265358979323846;
  // Tip rotation: the last section's curvature is carried to the tip (second order), measured
  // exact to 1e-9 for this uniform-curvature case; the .out keeps 10 significant digits.
  CHECK(std::abs(last("TipRDxr") - 4.0 * std::tan(pi / 8.0)) < 1e-8);
  CHECK(std::abs(last("TipRDxb1") - 90.0) < 1e-6);
  CHECK(std::abs(last("RootMxb1") - pi / 1000.0) < 1e-11);
  CHECK(last("B1RootMxr") == last("RootMxr"));
  CHECK(last("TipDyb1") == last("TipTDyr"));
}

TEST_CASE("a static beam run writes BeamDyn's ten rows: undeformed at t0, then the solution", "[unit][beam_scene]") {
  const auto dir = testing::scratch_dir("beam_scene_static_rows");
  RunRequest r = run_request(testing::source_dir() / "inputs/beams/rollup.yaml", dir / "run", std::string("h5"));
  r.beam_segments = 10;
  const RunReport report = run_scene(r, nullptr);
  CHECK(report.large_steps == 1);  // one static solve
  const io::ChannelTable t = io::read_hdf5_channels(dir / "run.h5");
  REQUIRE(t.rows() == 10);
  const std::vector<double>& moment = t.columns[*t.find("RootMxr")];
  CHECK(moment[0] == 0.0);
  for (std::size_t k = 1; k < t.rows(); ++k) {
    CHECK(t.time()[k] == static_cast<double>(k) * 0.005);  // the deck's default dt_s
    CHECK(moment[k] == moment[1]);
  }
  CHECK(std::abs(moment[1] - 4.0 * 3.14159265358979323846) < 1e-8);
}

TEST_CASE("a dynamic beam run from t0 > 0 writes the states of stepping the beam by hand", "[unit][beam_scene]") {
  const auto dir = testing::scratch_dir("beam_scene_dynamic_rows");
  const io::ValidatedDeck deck = io::read_deck(beam_scene_schema(), testing::source_dir() / "inputs/beams/rollup.yaml");
  BeamDynSetup setup{.definition = beam_definition(deck, "beam")};
  setup.gravity_m_s2 = Vec3(9.81, 0.0, 0.0);
  setup.angular_velocity_rad_s = Vec3(0.0, 0.0, 1.0);
  setup.dynamic = true;
  setup.t_initial_s = 1.0;
  setup.t_final_s = 1.02;
  setup.dt_s = 0.005;
  SingleBeamRun how;
  how.segments = 8;
  how.decimation = 2;
  run_single_beam(setup, how, run_request(dir / "hand_built", dir / "run", std::string("h5")), nullptr);

  const beam::BeamModel model = beam::discretise(setup.definition, how.segments);
  beam::DynamicStepper stepper(model, beam::DynamicOptions{});
  beam::BeamState state = beam::make_state(model);
  beam::BeamInput input;
  for (long k = 0; k < 4; ++k) step_beamdyn(setup, model, stepper, 1.0 + k * 0.005, 0.005, input, state);
  std::vector<double> values;
  beamdyn_channel_values(model, beam::beam_outputs(model, state), values);

  const io::ChannelTable t = io::read_hdf5_channels(dir / "run.h5");
  CHECK(t.time() == std::vector<double>{1.0, 1.0 + 2 * 0.005, 1.0 + 4 * 0.005});
  REQUIRE(t.columns.size() == values.size() + 1);
  for (std::size_t c = 0; c < values.size(); ++c) CHECK(t.columns[c + 1].back() == values[c]);
}

TEST_CASE("the cantilever pipe deck settles on the static deflection of its pipe", "[verification][beam_scene]") {
  // inputs/pipes/cantilever_flow.yaml is seed Table 3.1's last flow row (pipe_benchmarks::cantilever
  // at μ_V = 1.35) under a steady tip force: the flow damps the first mode hard (ζ = 0.52), so after
  // 2 s the tip rests where the static solve of the same pipe puts it. Measured difference 1.1e-9
  // of the deflection (the .out's 10 digits and what is left of the transient); bound 1e-8.
  const auto dir = testing::scratch_dir("pipe_scene_cantilever");
  run_scene(run_request(testing::source_dir() / "inputs/pipes/cantilever_flow.yaml", dir / "pipe"), nullptr);
  const io::ChannelTable t = io::read_channels(dir / "pipe.out");
  const beam::BeamModel model = beam::discretise_pipe(beam::pipe_benchmarks::cantilever(1.8e4, 0.5035, 1.35), 40);
  beam::BeamInput in;
  in.tip_load << 0.01, 0.0, 0.0, 0.0, 0.0, 0.0;
  beam::BeamState state = beam::make_state(model);
  beam::solve_static(model, in, state);
  const double expected = beam::beam_outputs(model, state).tip_displacement_m.x();
  const double tip = t.columns[*t.find("TipTDxr")].back();
  INFO("tip " << tip << " m, static " << expected << " m");
  CHECK(expected > 1e-4);
  CHECK(std::abs(tip / expected - 1.0) < 1e-8);
}

TEST_CASE("a pipe deck with a bore wider than its tube stops before the run, at the pipe", "[unit][beam_scene]") {
  const auto dir = testing::scratch_dir("pipe_scene_bad");
  const auto deck = dir / "pipe.yaml";
  std::ofstream(deck) << "simulation: {analysis: static}\npipe:\n  length_m: 1\n  outer_diameter_m: 0.02\n  inner_diameter_m: 0.03\n"
                         "  youngs_modulus_Pa: 1e9\n  density_kg_m3: 1000\n";
  CHECK_THROWS_WITH(run_scene(run_request(deck, dir / "run"), nullptr),
                    Catch::Contains("pipe.yaml:5") && Catch::Contains("inner_diameter_m"));
  CHECK_FALSE(std::filesystem::exists(dir / "run.out"));
}

TEST_CASE("the shipped riser decks are the seed's riser of modules/beam (riser::seed_case)", "[verification][beam_scene]") {
  // inputs/pipes/riser_{a,b,c,d}.yaml hold seed 000 §3.5.3's numbers as deck keys (sea, tip motion,
  // valves, static start); beam::riser::seed_case holds the same in code for the module's tests.
  // Each deck run for 0.5 s (the stretch ramp and the static start) against the module's loop: the
  // root loads agree to the .out's 10 digits (measured ≤ 2e-10 relative; bound 1e-8 — the two differ
  // by the frame origin, 300 m apart, and rounding).
  for (const char c : {'a', 'b', 'c', 'd'}) {
    const auto dir = testing::scratch_dir(std::string("pipe_scene_riser_") + c);
    RunRequest request = run_request(testing::source_dir() / fmt::format("inputs/pipes/riser_{}.yaml", c), dir / "riser");
    request.t_max_s = 0.5;
    request.output_format = "out";
    run_scene(request, nullptr);
    const io::ChannelTable t = io::read_channels(dir / "riser.out");

    const beam::riser::RiserSetup setup = beam::riser::seed_case(c);
    const beam::BeamModel model = beam::riser::riser_model(setup, 100);
    beam::BeamState state = beam::make_state(model);
    beam::BeamInput in;
    beam::riser::riser_input(setup, 0.0, in);
    beam::solve_static(model, in, state);
    beam::DynamicStepper stepper(model, beam::DynamicOptions{});
    for (int k = 0; k < 500; ++k) {
      beam::riser::riser_input(setup, (k + stepper.input_time_fraction()) * 1e-3, in);
      stepper.step(in, 1e-3, state);
    }
    const Vec6 root = beam::root_reaction(model, state);
    const double scale = root.head<3>().norm(), moment_scale = root.tail<3>().norm();
    INFO("case " << c << ": RootFzr " << t.columns[*t.find("RootFzr")].back() << " N, module " << root(2) << " N");
    CHECK(t.columns[*t.find("RootFzr")].back() == Approx(root(2)).margin(1e-8 * scale));
    CHECK(t.columns[*t.find("RootFyr")].back() == Approx(root(1)).margin(1e-8 * scale));
    CHECK(t.columns[*t.find("RootMxr")].back() == Approx(root(3)).margin(1e-8 * moment_scale));
  }
}

TEST_CASE("a pipe deck with a flowing closed valve or a moved free tip stops before the run, at the key", "[unit][beam_scene]") {
  const auto dir = testing::scratch_dir("pipe_scene_valve");
  const auto deck = dir / "pipe.yaml";
  const std::string pipe = "simulation: {analysis: dynamic, t_max_s: 0.01, dt_s: 0.001}\npipe:\n  length_m: 1\n  outer_diameter_m: 0.02\n"
                           "  inner_diameter_m: 0.01\n  youngs_modulus_Pa: 1e9\n  density_kg_m3: 1000\n";
  std::ofstream(deck) << pipe << "  tip_end: clamped\nfluid:\n  density_kg_m3: 1000\n  valve: closed_tip\n  velocity_m_s: 1.0\n";
  CHECK_THROWS_WITH(run_scene(run_request(deck, dir / "run"), nullptr),
                    Catch::Contains("pipe.yaml:12") && Catch::Contains("velocity_m_s") && Catch::Contains("closed valve"));
  std::ofstream(deck) << pipe << "tip_motion: {sway_amplitude_m: 0.1}\n";
  CHECK_THROWS_WITH(run_scene(run_request(deck, dir / "run"), nullptr),
                    Catch::Contains("pipe.yaml:8") && Catch::Contains("tip_motion") && Catch::Contains("held tip"));
  std::ofstream(deck) << pipe << "root: {angular_velocity_rad_s: [0, 0, 1]}\nsea: {drag_coefficient: 1.0}\n";
  CHECK_THROWS_WITH(run_scene(run_request(deck, dir / "run"), nullptr),
                    Catch::Contains("pipe.yaml:8") && Catch::Contains("angular_velocity_rad_s"));
  CHECK_FALSE(std::filesystem::exists(dir / "run.out"));
  CHECK_FALSE(std::filesystem::exists(dir / "run.h5"));
}
