// The coupled NREL 5MW on OC3-Hywind (rigid multibody, BEM rotor, OC3 baseline controller, Morison
// hydro, hydrostatics, catenary) in steady wind: the closed loop settles at rated rotor speed with
// the published blade pitch (issue 6, verification 3, here through our own aerodynamics).
#include <fstream>
#include <numeric>

#include <catch2/catch.hpp>

#include "fowtsim/io/readers.hpp"
#include "fowtsim/testing/skip.hpp"
#include "run/run_scene.hpp"
#include "run_request.hpp"
#include "test_helpers.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

TEST_CASE("OC3-Hywind in steady wind settles at rated speed with the published pitch", "[verification][coupled]") {
  const auto dir = testing::scratch_dir("coupled_steady");
  // Published operating table (PUBLISHED.md, welib NREL5MW_Oper.csv from OpenFAST): pitch 3.45°,
  // 10.26°, 17.32° at 12, 15, 20 m/s, rotor speed 12.1 rpm.
  const struct {
    double wind, pitch_deg;
  } points[] = {{12.0, 3.45}, {15.0, 10.26}, {20.0, 17.32}};
  for (const auto& p : points) {
    const auto deck = dir / "turbine.yaml";
    std::ofstream(deck) << "include: [" << (testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml").string() << "]\n"
                        << "simulation: {t_max_s: 250.0, dt_s: 0.0125}\noutput: {format: out, decimation: 8}\n"
                        << "wind: {model: steady, speed_m_s: " << p.wind << ", reference_height_m: 90.0}\n";
    run_scene(run_request(deck, dir / "run", std::nullopt), nullptr);
    const io::ChannelTable t = io::read_channels(dir / "run.out");
    INFO(p.wind << " m/s: pitch " << mean_after(t, "BldPitch1", 200.0) << "°, rotor " << mean_after(t, "RotSpeed", 200.0) << " rpm");
    // Issue 6: within 0.5° of the table. The table is the land-based turbine; on the spar the
    // rotor also pitches back with the platform (4° at 12 m/s), which the loop answers with more
    // blade pitch. Measured: +0.31°, +0.07°, −0.03°.
    CHECK(std::abs(mean_after(t, "BldPitch1", 200.0) - p.pitch_deg) < 0.5);
    // Rated speed 12.1 rpm held by the pitch loop: 1 % (the detuned OC3 gains settle slowly; at
    // 12 m/s measured +0.6 % at 200–250 s).
    CHECK(std::abs(mean_after(t, "RotSpeed", 200.0) / 12.1 - 1.0) < 0.01);
  }
}
