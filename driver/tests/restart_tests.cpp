// Checkpoints and restarts (issue 16): a run restarted from a checkpoint continues bit-identically
// to the uninterrupted run, on the rigid-blade and the flexible-blade turbine, and its output
// holds the whole run (the rows before the checkpoint copied from the interrupted run's output).
#include <fstream>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"
#include "fowtsim/testing/skip.hpp"
#include "run/run_scene.hpp"
#include "run_request.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

void check_restart(const std::filesystem::path& deck, const std::string& overrides, const std::string& name) {
  const auto dir = testing::scratch_dir("restart_" + name);
  std::ofstream(dir / "deck.yaml") << "include: [" << deck.string() << "]\noutput: {format: h5, decimation: 1}\n" << overrides;
  // Uninterrupted, with a checkpoint every 4 s: one, at 4 s, in whole.chk.
  RunRequest whole = run_request(dir / "deck.yaml", dir / "whole", "h5");
  whole.t_max_s = 6.0;
  whole.checkpoint_every_s = 4.0;
  run_scene(whole, nullptr);
  RunRequest restarted = run_request(dir / "deck.yaml", dir / "restarted", "h5");
  restarted.t_max_s = 6.0;
  restarted.restart_path = dir / "whole.chk";
  run_scene(restarted, nullptr);
  const io::ChannelTable a = io::read_channels(dir / "whole.h5");
  const io::ChannelTable b = io::read_channels(dir / "restarted.h5");
  REQUIRE(a.names == b.names);
  // The restarted output continues the checkpoint's run (whole.h5): its rows before 4 s are copied
  // from it, those from 4 s on are computed again and must be the same bit for bit, every channel.
  REQUIRE(b.rows() == a.rows());
  REQUIRE(b.time().front() == 0.0);
  for (std::size_t c = 0; c < a.names.size(); ++c)
    for (std::size_t i = 0; i < b.rows(); ++i) {
      INFO(a.names[c] << " at t = " << b.time()[i]);
      REQUIRE(a.columns[c][i] == b.columns[c][i]);
    }
}

}  // namespace

TEST_CASE("a restart continues the rigid-blade turbine bit-identically", "[verification][run]") {
  check_restart(testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml",
                "waves: {model: jonswap, hs_m: 4.0, tp_s: 9.0, seed: 3, duration_s: 200.0, dt_s: 0.25, depth_m: 320.0}\n",
                "rigid");
}

TEST_CASE("a restart continues the flexible-blade turbine bit-identically", "[verification][run]") {
  check_restart(testing::source_dir() / "inputs/oc3_hywind/turbine_flexible_ntm_12mps_irregular.yaml", "", "flexible");
}

TEST_CASE("a restart continues MBBT blades on the flexible tower bit-identically (their apparent mass in the state)",
          "[verification][run][interface_mass]") {
  check_restart(testing::source_dir() / "inputs/oc3_hywind/turbine_flexible_ntm_12mps_irregular.yaml",
                "structure: {tower: {flexible: true}}\n", "flexible_tower_blades");
}

TEST_CASE("a restart continues the turbine with unsteady airfoils and dynamic inflow bit-identically", "[verification][run]") {
  // Rigid blades (states advanced once per large step) and flexible blades (at the small step).
  const std::string on = "aero: {unsteady_airfoil: hgm, dynamic_inflow: oye}\n";
  check_restart(testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml",
                on + "waves: {model: jonswap, hs_m: 4.0, tp_s: 9.0, seed: 3, duration_s: 200.0, dt_s: 0.25, depth_m: 320.0}\n",
                "rigid_unsteady_aero");
  check_restart(testing::source_dir() / "inputs/oc3_hywind/turbine_flexible_ntm_12mps_irregular.yaml", on,
                "flexible_unsteady_aero");
}

TEST_CASE("a restart continues control events bit-identically", "[verification][run]") {
  // Events fired before the 4 s checkpoint (a stuck blade at 1 s, a grid loss at 3 s) and after it
  // (the grid loss's shutdown at 4.5 s), a brake whose ramp (3.8–4.4 s) spans it, an overspeed
  // condition watched throughout (GenSpeed peaks at 1239.6 rpm: it does not fire): which fired,
  // when, the contactor and the brake's engagement are in the checkpointed controller data.
  check_restart(testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml",
                "structure: {initial_conditions: {blade_pitch_deg: 10.0}}\n"
                "controller:\n  events:\n    - {type: pitch_stuck, at_s: 1.0, blade: 3}\n"
                "    - {type: grid_loss, at_s: 3.0, shutdown_delay_s: 1.5}\n"
                "    - {type: brake, at_s: 3.8}\n"
                "    - {type: emergency_stop, when: {channel: GenSpeed, above: 1250.0}}\n",
                "events");
  // Flexible blades: a brake slipping across the checkpoint (emergency stop at 3.5 s), and a
  // parked rotor whose drivetrain lock (the spin's) is in the checkpointed blade state.
  check_restart(testing::source_dir() / "inputs/oc3_hywind/turbine_flexible_ntm_12mps_irregular.yaml",
                "controller:\n  events:\n    - {type: emergency_stop, at_s: 3.5}\n", "flexible_events");
  check_restart(testing::source_dir() / "inputs/oc3_hywind/turbine_flexible_ntm_12mps_irregular.yaml",
                "structure: {initial_conditions: {rotor_speed_rpm: 0.0}}\ncontroller: {operating_mode: parked}\n",
                "flexible_parked");
}

TEST_CASE("a restart continues the toy oscillators bit-identically (the scheduler's state whole)", "[unit][run]") {
  // Slow and fast states, the held loads, the last frame motion and root loads, the step count.
  check_restart(testing::source_dir() / "inputs/toy_coupled_oscillators.yaml", "", "toy");
  check_restart(testing::source_dir() / "inputs/toy_coupled_oscillators.yaml", "simulation: {coupling: predictor_corrector}\n",
                "toy_predictor_corrector");
}

TEST_CASE("a checkpoint of another deck or step is refused before the run", "[unit][run]") {
  const auto dir = testing::scratch_dir("restart_refused");
  const auto deck = testing::source_dir() / "inputs/oc3_hywind/free_decay_pitch.yaml";
  RunRequest first = run_request(deck, dir / "first", "h5");
  first.t_max_s = 1.0;
  first.checkpoint_every_s = 0.5;
  run_scene(first, nullptr);
  RunRequest other = run_request(testing::source_dir() / "inputs/oc3_hywind/free_decay_surge.yaml", dir / "other", "h5");
  other.t_max_s = 1.0;
  other.restart_path = dir / "first.chk";
  CHECK_THROWS_AS(run_scene(other, nullptr), InputError);
  CHECK_FALSE(std::filesystem::exists(dir / "other.h5"));
  RunRequest bad_every = run_request(deck, dir / "bad", "h5");
  bad_every.checkpoint_every_s = 0.0123;
  CHECK_THROWS_AS(run_scene(bad_every, nullptr), InputError);
}

TEST_CASE("a restart continues a turbine on WAMIT potential flow in waves bit-identically (convolution and state space)",
          "[verification][run]") {
  // The radiation memory (history ring or modal states, and the stage sums) is part of the state.
  (void)testing::shared_dir_or_skip();  // the WAMIT files live beside the reference data
  const std::string sea =
      "waves: {model: jonswap, hs_m: 4.0, tp_s: 9.0, seed: 3, duration_s: 200.0, dt_s: 0.25, depth_m: 320.0}\n";
  for (const char* method : {"convolution", "state_space"}) {
    const auto dir = testing::scratch_dir(std::string("restart_wamit_deck_") + method);
    std::ofstream(dir / "deck.yaml") << "include: [" << (testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml").string()
                                     << ", " << (testing::source_dir() / "inputs/oc3_hywind/hydro_potential_flow.yaml").string()
                                     << "]\nhydro: {potential_flow: {radiation: " << method << "}}\n";
    check_restart(dir / "deck.yaml", sea, std::string("wamit_") + method);
  }
}

TEST_CASE("a restart continues the turbine with a riser hung from the spar bit-identically", "[verification][run][riser]") {
  // In an irregular sea: the line takes its wave kinematics at every small step.
  check_restart(testing::source_dir() / "inputs/oc3_hywind/turbine_riser_15mps.yaml",
                "waves: {model: jonswap, hs_m: 4.0, tp_s: 9.0, seed: 3, duration_s: 200.0, dt_s: 0.25, depth_m: 320.0}\n", "riser");
}
