// The run summary says what a scene coupled and warns about inputs far outside sense (issue 16).
#include <fstream>

#include <catch2/catch.hpp>

#include "fowtsim/testing/skip.hpp"
#include "run/run_scene.hpp"
#include "h5_attributes.hpp"
#include "run_request.hpp"

using namespace fowtsim;
using namespace fowtsim::driver;

namespace {
bool any_contains(const std::vector<std::string>& lines, const std::string& text) {
  for (const std::string& l : lines)
    if (l.find(text) != std::string::npos) return true;
  return false;
}
}  // namespace

TEST_CASE("a free decay's summary names what it coupled: no aerodynamics, no controller", "[unit][run]") {
  const auto dir = testing::scratch_dir("summary_free_decay");
  RunRequest r = run_request(testing::source_dir() / "inputs/oc3_hywind/free_decay_pitch.yaml", dir / "run");
  r.t_max_s = 1.0;
  const RunReport report = run_scene(r, nullptr);
  CHECK(report.coupling.find("no aerodynamics") != std::string::npos);
  CHECK(report.coupling.find("no controller") != std::string::npos);
  CHECK(report.warnings.empty());
}

TEST_CASE("a sea steeper than the breaking limit and a rotor overspeed are warned about", "[unit][run]") {
  const auto dir = testing::scratch_dir("summary_warnings");
  // Hs 40 m at Tp 10 s: H/L = 0.26 against the breaking limit 1/7.
  std::ofstream(dir / "steep.yaml") << "include: [" << (testing::source_dir() / "inputs/oc3_hywind/free_decay_pitch.yaml").string()
                                    << "]\nwaves: {model: jonswap, hs_m: 40.0, tp_s: 10.0, seed: 1, duration_s: 100.0, dt_s: 0.25, "
                                       "depth_m: 320.0}\n";
  RunRequest steep = run_request(dir / "steep.yaml", dir / "steep", "h5");
  steep.t_max_s = 1.0;
  CHECK(any_contains(run_scene(steep, nullptr).warnings, "breaking limit"));
  // The HDF5 keeps them too.
  CHECK(string_attribute(dir / "steep.h5", "warnings").find("breaking limit") != std::string::npos);
  // Started at 20 rpm with the built-in controller (rated 12.1 rpm): more than 30 % above.
  std::ofstream(dir / "fast.yaml") << "include: [" << (testing::source_dir() / "inputs/oc3_hywind/turbine_steady_15mps.yaml").string()
                                   << "]\nstructure: {initial_conditions: {rotor_speed_rpm: 20.0}}\n";
  RunRequest fast = run_request(dir / "fast.yaml", dir / "fast");
  fast.t_max_s = 0.5;
  CHECK(any_contains(run_scene(fast, nullptr).warnings, "overspeed"));
}
