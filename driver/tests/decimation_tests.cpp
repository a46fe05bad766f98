// Output decimation changes nothing (issue 16): writing a row evaluates the loads between steps,
// and must leave every solver's memory (mooring and BEM warm starts) as the step left it.
#include <fstream>

#include <catch2/catch.hpp>

#include "fowtsim/io/readers.hpp"
#include "fowtsim/testing/skip.hpp"
#include "run/run_scene.hpp"
#include "run_request.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

// Every channel of the decimated run equals the full run's at the common times, bit for bit.
void check_same_at_common_times(const std::filesystem::path& deck, const std::string& overrides) {
  const auto dir = testing::scratch_dir("decimation_" + deck.stem().string());
  for (const int decimation : {1, 7}) {
    std::ofstream(dir / "deck.yaml") << "include: [" << deck.string() << "]\n"
                                     << "output: {format: h5, decimation: " << decimation << "}\n"
                                     << overrides;
    RunRequest r = run_request(dir / "deck.yaml", dir / ("every" + std::to_string(decimation)), "h5");
    r.t_max_s = 7.0;
    run_scene(r, nullptr);
  }
  const io::ChannelTable all = io::read_channels(dir / "every1.h5");
  const io::ChannelTable some = io::read_channels(dir / "every7.h5");
  REQUIRE(some.rows() > 2);
  REQUIRE(all.names == some.names);
  long compared = 0;
  for (std::size_t c = 0; c < all.names.size(); ++c)
    for (std::size_t i = 0; i < some.rows(); ++i) {
      INFO(all.names[c] << " at t = " << some.time()[i]);
      REQUIRE(all.columns[c][7 * i] == some.columns[c][i]);
      ++compared;
    }
  CHECK(compared > 100);
}

}  // namespace

TEST_CASE("output decimation does not change a rigid-blade turbine's results", "[verification][run]") {
  // BEM at every RK stage (warm-started), catenary mooring (warm-started), sea, controller.
  check_same_at_common_times(testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml",
                             "waves: {model: jonswap, hs_m: 4.0, tp_s: 9.0, seed: 3, duration_s: 200.0, dt_s: 0.25, depth_m: 320.0}\n");
}

TEST_CASE("output decimation does not change a flexible-blade turbine's results", "[verification][run]") {
  check_same_at_common_times(testing::source_dir() / "inputs/oc3_hywind/turbine_flexible_ntm_12mps_irregular.yaml",
                             "wind: {model: steady, speed_m_s: 12.0, reference_height_m: 90.0}\n");
}

TEST_CASE("output decimation does not change a turbine with unsteady airfoils and dynamic inflow", "[verification][run]") {
  // The rows evaluate the rotor with the unsteady states of the last step and must leave them,
  // and the BEM warm starts, as they were.
  check_same_at_common_times(testing::source_dir() / "inputs/oc3_hywind/turbine_ntm_12mps_irregular_unsteady_aero.yaml",
                             "wind: {model: steady, speed_m_s: 12.0, reference_height_m: 90.0}\n");
}

TEST_CASE("output decimation does not change the platform-loads scene's results", "[verification][run]") {
  // The catenary mooring is warm-started from the previous evaluation, made at every step.
  check_same_at_common_times(testing::source_dir() / "inputs/oc3_hywind/platform_in_waves.yaml", "");
}
