// Rayleigh–Ritz blades started at their static deflection (structure.initial_conditions.
// blade_deflection: static, what a sweep's trim sets): the blades' elastic rows are settled under
// gravity, the aerodynamic loads and the spin of the initial state (FloatingScene::settle_elastic,
// blades_in_motion), so a steady case starts where it stays instead of ringing from undeflected
// blades (ElastoDyn's OoPDefl = IPDefl = 0 start, the default).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <string>

#include "fowtsim/io/readers.hpp"
#include "fowtsim/testing/skip.hpp"
#include "run/run_scene.hpp"
#include "run_request.hpp"
#include "test_helpers.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {

// The OC3 turbine held still, the rotor held at 12.1 rpm, pitch 10° without a controller, in steady
// 15 m/s: the blades' only motion is their own.
io::ChannelTable run_rr(const std::string& name, const std::string& deflection) {
  const auto dir = testing::scratch_dir("rr_static_start_" + name);
  const auto inputs = testing::source_dir() / "inputs";
  std::ofstream(dir / "deck.yaml")
      << "include: [" << (inputs / "oc3_hywind/structure.yaml").string() << ", " << (inputs / "oc3_hywind/aero_oc3.yaml").string()
      << "]\nsimulation: {t_max_s: 14.0, dt_s: 0.0125}\noutput: {format: h5, decimation: 1, channels: [OoPDefl1, IPDefl1]}\n"
      << "wind: {model: steady, speed_m_s: 15.0, reference_height_m: 90.0}\n"
      << "structure:\n  rotor: {rayleigh_ritz_blade_file: " << (inputs / "nrel5mw/blade_elastodyn.yaml").string() << "}\n"
      << "  initial_conditions: {rotor_speed_rpm: 12.1, blade_pitch_deg: 10.0, blade_deflection: " << deflection << "}\n"
      << "  degrees_of_freedom: {surge: false, sway: false, heave: false, roll: false, pitch: false, yaw: false, rotor_speed: held}\n";
  run_scene(run_request(dir / "deck.yaml", dir / "run", "h5"), nullptr);
  return io::read_channels(dir / "run.h5");
}

// Largest |x(t) − x(t + 2T)| over the first 2 s, T = 60/12.1 s the rotor's period (x at t + 2T
// linearly interpolated between rows): the start's transient, apart from the periodic response to
// gravity and the tower's potential flow that the held rotor repeats every turn.
double start_transient(const io::ChannelTable& t, const char* name) {
  const std::vector<double>& time = t.time();
  const std::vector<double>& x = column(t, name);
  const double period = 60.0 / 12.1;
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size() && time[i] <= 2.0; ++i) {
    const double later = time[i] + 2.0 * period;
    const auto j = static_cast<std::size_t>(std::upper_bound(time.begin(), time.end(), later) - time.begin());
    REQUIRE((j > 0 && j < x.size()));
    const double w = (later - time[j - 1]) / (time[j] - time[j - 1]);
    worst = std::max(worst, std::abs(x[i] - ((1.0 - w) * x[j - 1] + w * x[j])));
  }
  return worst;
}

}  // namespace

TEST_CASE("Rayleigh-Ritz blades start at their static deflection: no start-up ringing", "[verification][run]") {
  const io::ChannelTable settled = run_rr("static", "static"), plain = run_rr("undeflected", "undeflected");
  const double mean_flap = [&] {
    const std::vector<double>& x = column(plain, "OoPDefl1");
    return std::accumulate(x.end() - 400, x.end(), 0.0) / 400.0;
  }();
  INFO("static start: OoPDefl1(0) " << column(settled, "OoPDefl1").front() << " m, transient " << start_transient(settled, "OoPDefl1")
                                    << " m (IPDefl1 " << start_transient(settled, "IPDefl1") << " m); undeflected: "
                                    << start_transient(plain, "OoPDefl1") << " m (" << start_transient(plain, "IPDefl1")
                                    << " m); late mean " << mean_flap << " m");
  CHECK(column(plain, "OoPDefl1").front() == 0.0);  // ElastoDyn's default start
  CHECK(column(settled, "OoPDefl1").front() > 0.5 * mean_flap);
  // Measured: static start 0.061 m (flap) and 0.064 m (edge), undeflected 2.48 m and 0.73 m. What
  // the static start leaves is the difference between the quasi-static and the periodic response to
  // the turning gravity load (1P at 0.2 Hz on the 0.7 Hz flap and 1.1 Hz edge modes: a few % of
  // their gravity amplitude). Bounds 0.3 m (≈ 5× measured, so the residual's source could double and
  // still pass; an unsettled start is ≥ 2.5× above them).
  CHECK(start_transient(settled, "OoPDefl1") < 0.3);
  CHECK(start_transient(settled, "IPDefl1") < 0.3);
  CHECK(start_transient(plain, "OoPDefl1") > 1.0);
  CHECK(start_transient(plain, "IPDefl1") > 0.5);
}
